// hexadapt-assign: majority assignment and manifold correction of a grid with volume
// fractions (paper sec. 3). Reads any mesh file with fraction arrays, writes the same grid
// and fractions plus Int32 cell arrays `material` (final) and `majority` (initial).
#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include "cli.h"
#include "hexadapt/assign/assign.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/rank_files.h"
#include "hexadapt/mesh/cell_complex.h"
#include "input_record.h"
#include "ranks.h"

namespace hexadapt {
namespace {

struct Options {
  cli::CommonOptions common;
  std::string input;
  std::string partial;
  cli::InputOptions in;
  assign::AssignOptions assign;
  bool paper_order = false;
  bool gather = false;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("input", o.input,
                 "Grid with volume fractions (.vtu .vtk .vti .vtr .vts .pvtu .pvtr .pvts .vtm "
                 ".pvd .txt .exo)")
      ->required();
  cli::add_common_options(app, o.common);
  cli::add_write_options(app, o.common);
  cli::add_input_options(app, o.in);
  app.add_option("--keep", o.assign.correction.keep, "Manifold configurations stored per node")
      ->check(cli::positive)
      ->capture_default_str();
  app.add_option("--max-materials", o.assign.correction.max_materials,
                 "Candidate materials per node (the most present in its ball)")
      ->check(cli::positive)
      ->capture_default_str();
  app.add_option("--max-leaves", o.assign.correction.max_leaves,
                 "Per node: complete configurations examined at most")
      ->check(cli::positive)
      ->capture_default_str();
  app.add_option("--min-island", o.assign.min_island,
                 "Pieces of one material (cells joined by faces) with fewer cells than this go "
                 "to the material around them most present in their cells, before the manifold "
                 "correction (0: off)")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_flag("--keep-materials", o.assign.keep_materials,
               "Give a material that is nowhere the majority the cells where it is most present "
               "(as many as its volume fills, at least one), before the manifold correction");
  app.add_flag("--paper-order", o.paper_order,
               "Take stored configurations strictly by cost (do not prefer ones that keep "
               "neighbouring nodes manifold)");
  app.add_option("--partial", o.partial,
                 "When the correction fails, write the assignment reached so far here");
  app.add_flag("--gather", o.gather,
               "Under mpirun on several ranks: write one file of the whole grid (any format) "
               "instead of a piece per rank (.vtu or .vts) and the .pvtu or .pvts naming them");
}

/// The input data plus the assigned grid's arrays (io::put_assignment), the majority
/// assignment, provenance and the record of how the fractions were read (`record`,
/// input_record.h).
io::MeshData output_data(io::MeshData data, const AssignedGrid& grid, const CellMaterials& majority,
                         const CLI::App& app, const std::string& record) {
  io::put_assignment(grid, data);
  io::DataArray a;
  a.name = "majority";
  a.type = io::ScalarType::int32;
  a.values.assign(majority.begin(), majority.end());
  data.set_cell_array(std::move(a));
  for (const auto& kv : cli::provenance(app)) data.metadata.push_back(kv);
  auto& meta = data.metadata;
  meta.erase(std::remove_if(meta.begin(), meta.end(),
                            [](const auto& kv) { return kv.first == cli::input_record_key; }),
             meta.end());
  meta.emplace_back(cli::input_record_key, record);
  return data;
}

cli::Json failure_json(const assign::CorrectionFailure& f, const Fractions& fractions) {
  cli::Json j;
  j["node"] = f.node.value();
  j["position"] = {f.position.x(), f.position.y(), f.position.z()};
  cli::Json names = cli::Json::array();
  for (int m : f.materials) names.push_back(fractions.names()[static_cast<std::size_t>(m)]);
  j["materials"] = names;
  j["stored_configurations"] = f.stored;
  return j;
}

cli::Json result_json(const assign::AssignResult& r, const io::FractionReport& fr) {
  const auto& c = r.correction;
  cli::Json j;
  const FractionTolerances& t = fr.tolerances;
  j["fractions"] = {{"clipped_values", fr.clipped_values},
                    {"zeroed_values", fr.zeroed_values},
                    {"rescaled_cells", fr.rescaled_cells},
                    {"max_sum_error", fr.max_sum_error},
                    {"stored_precision", precision_name(fr.precision)},
                    {"float32_rounding", t.float32_rounding},
                    {"sum_tolerance", t.sum_tolerance},
                    {"sum_tolerance_given", t.sum_tolerance_given},
                    {"zero_below", t.zero_below},
                    {"zero_below_given", t.zero_below_given}};
  j["non_manifold_nodes_initial"] = c.non_manifold_initial;
  j["solved"] = c.solved;
  j["iterations"] = c.rounds;
  j["node_solves"] = c.node_solves;
  j["nodes_treated"] = c.nodes_treated;
  j["max_configurations_used"] = c.max_visits;
  j["cells_changed"] = c.cells_changed;
  j["cost_majority"] = c.cost_initial;
  j["cost_final"] = c.cost_final;
  j["cost_added"] = c.cost_final - c.cost_initial;
  j["configurations_examined"] = c.leaves;
  j["truncated_enumerations"] = c.truncated_enumerations;
  return j;
}

cli::Json balance_json(const std::vector<assign::MaterialBalance>& balance,
                       const Fractions& fractions) {
  cli::Json out = cli::Json::array();
  for (std::size_t m = 0; m < balance.size(); ++m)
    out.push_back({{"name", fractions.names()[m]},
                   {"input_volume", balance[m].input_volume},
                   {"input_share", balance[m].input_share},
                   {"assigned_volume", balance[m].assigned_volume},
                   {"assigned_cells", balance[m].assigned_cells}});
  return out;
}

// What io::extract_fractions decided and did: the precision, the tolerances and where they came
// from, and the repairs.
std::string fractions_message(const io::FractionReport& fr) {
  const FractionTolerances& t = fr.tolerances;
  std::ostringstream s;
  s << "fractions stored as " << precision_name(fr.precision);
  if (fr.precision == StoredPrecision::float32)
    s << " (their rounding in a cell: at most " << std::setprecision(2) << t.float32_rounding
      << std::setprecision(6) << ")";
  s << ": sums within " << t.sum_tolerance << " of 1 rescaled ("
    << (t.sum_tolerance_given ? "--sum-tolerance" : "default") << "), fractions below "
    << t.zero_below << " set to 0 (" << (t.zero_below_given ? "--zero-below" : "default") << "); "
    << fr.rescaled_cells << " cells rescaled, " << fr.zeroed_values << " traces set to 0, "
    << fr.clipped_values << " values clipped into [0, 1]";
  return s.str();
}

// What --min-island did, and the small pieces the correction left (a warning: asked away).
void log_islands(const assign::AssignResult& r, index_t min_cells) {
  log_info(std::to_string(r.islands.islands) + " pieces smaller than " + std::to_string(min_cells) +
           " cells (" + std::to_string(r.islands.cells) +
           " cells) given to the material around them");
  if (r.small_pieces_final > 0)
    log_warning(std::to_string(r.small_pieces_final) + " pieces smaller than " +
                std::to_string(min_cells) + " cells remain after the manifold correction");
}

// A material nowhere the majority gets no cell and is gone from every later stage.
void warn_vanished(const std::vector<assign::MaterialBalance>& balance,
                   const Fractions& fractions) {
  for (std::size_t m = 0; m < balance.size(); ++m) {
    if (!balance[m].vanished()) continue;
    char share[32];
    std::snprintf(share, sizeof share, "%.3g", 100 * balance[m].input_share);
    log(LogLevel::warning, "material '" + fractions.names()[m] +
                               "' has no cell after the "
                               "assignment: it is nowhere the majority (" +
                               share +
                               " % of the domain's volume in the input); it is lost to every "
                               "later stage");
  }
}

std::string failure_message(const assign::CorrectionFailure& f, const Fractions& fractions,
                            int keep) {
  std::ostringstream s;
  s << "manifold correction failed at node " << f.node.value() << " (" << f.position.x() << ", "
    << f.position.y() << ", " << f.position.z() << "), materials";
  for (std::size_t i = 0; i < f.materials.size(); ++i)
    s << (i ? ", " : " ") << fractions.names()[static_cast<std::size_t>(f.materials[i])];
  s << ": all " << f.stored << " stored configurations were used; rerun with a larger --keep"
    << " (now " << keep << ")";
  return s.str();
}

// The logs of an assignment, on every run.
void log_result(const assign::AssignResult& r, const Options& o, const Fractions& fractions) {
  log_info("non-manifold nodes at first: " + std::to_string(r.correction.non_manifold_initial) +
           ", cells changed: " + std::to_string(r.correction.cells_changed));
  if (o.assign.min_island > 1) log_islands(r, o.assign.min_island);
  for (const assign::KeptMaterial& k : r.kept)
    log_info("material '" + fractions.names()[static_cast<std::size_t>(k.material)] +
             "', nowhere the majority, kept in the " + std::to_string(k.cells) +
             " cells where it is most present");
  warn_vanished(r.balance, fractions);
}

// The report, the failure message and the exit code.
int finish(const CLI::App& app, const Options& o, const assign::AssignResult& r,
           const io::FractionReport& fr, const Fractions& fractions, int dimension,
           std::int64_t cells, const std::string& out, PhaseTimes times,
           const cli::Json& ranks = nullptr) {
  cli::Json report = cli::report_header(app);
  report["input"] = o.input;
  report["output"] = out;
  report["dimension"] = dimension;
  report["cells"] = cells;
  report["materials"] = fractions.names();
  report["options"] = {{"keep", o.assign.correction.keep},
                       {"min_island", o.assign.min_island},
                       {"keep_materials", o.assign.keep_materials},
                       {"max_materials", o.assign.correction.max_materials},
                       {"max_leaves", o.assign.correction.max_leaves},
                       {"paper_order", o.paper_order}};
  report["assign"] = result_json(r, fr);
  report["assign"]["materials"] = balance_json(r.balance, fractions);
  report["assign"]["kept"] = cli::Json::array();
  for (const assign::KeptMaterial& k : r.kept)
    report["assign"]["kept"].push_back(
        {{"name", fractions.names()[static_cast<std::size_t>(k.material)]}, {"cells", k.cells}});
  report["assign"]["islands"] = {{"reassigned", r.islands.islands},
                                 {"cells", r.islands.cells},
                                 {"left", r.islands.left},
                                 {"small_pieces_final", r.small_pieces_final}};
  if (r.correction.failure)
    report["assign"]["failure"] = failure_json(*r.correction.failure, fractions);
  report["exit_code"] = r.correction.failure ? cli::target_missed : cli::ok;
  report["times"] = cli::phase_times_json(times);
  if (!ranks.is_null()) report["ranks"] = ranks;
  cli::write_report(o.common, report);
  if (r.correction.failure) {
    log(LogLevel::error,
        failure_message(*r.correction.failure, fractions, o.assign.correction.keep));
    return cli::target_missed;
  }
  return cli::ok;
}

int run_assign(const CLI::App& app, Options& o) {
  cli::check_files(
      {{"input", o.input}},
      {{"-o", o.common.output, true}, {"--partial", o.partial, true}, {"--json", o.common.json}});
  PhaseTimes times;
  Timer t;
  io::MeshData data = io::read_mesh(o.input, o.in.read_options());
  // The output is the input's grid: a .vts needs a structured input.
  for (const std::string& out : {o.common.output, o.partial})
    if (!out.empty()) io::check_mesh_output(out, data.is_structured());
  cli::check_memory("assigning " + std::to_string(data.n_cells()) + " cells",
                    static_cast<double>(data.n_cells()) * cli::assign_bytes_per_cell,
                    o.common.memory_limit());
  times.emplace_back("read", t.seconds());
  t.restart();
  io::FractionReport fr;
  AssignedGrid grid = io::to_assigned_grid(data, o.in.grid(io::MaterialSource::none), o.input, &fr);
  const Fractions& fractions = grid.fractions;
  if (o.in.fractions.labels.empty()) log_info(fractions_message(fr));
  times.emplace_back("fractions", t.seconds());
  const assign::AssignResult r = assign::assign_materials(grid, o.assign);
  for (const auto& p : r.times) times.push_back(p);
  log_result(r, o, fractions);
  t.restart();
  const std::string out = r.correction.solved ? o.common.output : o.partial;
  grid.material = r.correction.labels;
  if (!out.empty())
    io::write_mesh(output_data(std::move(data), grid, r.majority, app, cli::input_record(o.in, fr)),
                   out, o.common.write_options());
  times.emplace_back("write", t.seconds());
  const int dimension =
      std::visit([](const auto& m) { return std::decay_t<decltype(m)>::dim; }, grid.mesh);
  return finish(app, o, r, fr, fractions, dimension, fractions.n_cells(), out, times);
}

// The fraction report of the whole grid from every rank's report of the cells it owns.
io::FractionReport whole_report(const dist::Communicator& comm, io::FractionReport fr) {
  fr.clipped_values = dist::sum_in_rank_order(comm, fr.clipped_values);
  fr.zeroed_values = dist::sum_in_rank_order(comm, fr.zeroed_values);
  fr.rescaled_cells = dist::sum_in_rank_order(comm, fr.rescaled_cells);
  const std::vector<double> errors = dist::all_gather_values(comm, std::vector{fr.max_sum_error});
  fr.max_sum_error = *std::max_element(errors.begin(), errors.end());
  return fr;
}

// On the ranks of an MPI job: each reads its slab of a structured grid, or holds its part of
// an unstructured mesh cut by PT-Scotch (two ghost layers either way: the correction looks two
// cells around the nodes it owns), and writes the cells it owns.
int run_assign_on_ranks(const CLI::App& app, Options& o, const dist::Communicator& comm) {
  dist::on_every_rank(comm, [&] {
    cli::check_files(
        {{"input", o.input}},
        {{"-o", o.common.output, true}, {"--partial", o.partial, true}, {"--json", o.common.json}});
    const bool structured = !io::holds_unstructured_mesh(o.input);
    cli::check_rank_output("-o", o.common.output, o.gather, structured);
    cli::check_rank_output("--partial", o.partial, o.gather, structured);
  });
  PhaseTimes times;
  Timer t;
  io::RankInput in = io::read_mesh_on_ranks(comm, o.input, o.in.read_options(), 2);
  dist::on_every_rank(comm, [&] {
    cli::check_memory("assigning " + std::to_string(in.data.n_cells()) + " cells on this rank",
                      static_cast<double>(in.data.n_cells()) * cli::assign_bytes_per_cell,
                      o.common.memory_limit());
  });
  times.emplace_back("read", t.seconds());
  t.restart();
  io::FractionReport fr;
  AssignedGrid grid;
  if (!o.in.fractions.labels.empty())
    o.in.fractions.label_values = cli::grid_labels(comm, o.in, o.input, in);
  dist::on_every_rank(comm, [&] {
    grid = io::to_assigned_grid(in.data, o.in.grid(io::MaterialSource::none), o.input, &fr,
                                &in.slab.block);
  });
  fr = whole_report(comm, fr);
  const Fractions& fractions = grid.fractions;
  if (o.in.fractions.labels.empty()) log_info(fractions_message(fr));
  times.emplace_back("fractions", t.seconds());
  const dist::Distribution where{comm, in.slab.block};
  const assign::AssignResult r = std::visit(
      [&](const auto& mesh) { return assign::assign_materials(mesh, fractions, o.assign, where); },
      grid.mesh);
  for (const auto& p : r.times) times.push_back(p);
  log_result(r, o, fractions);
  t.restart();
  const std::string out = r.correction.solved ? o.common.output : o.partial;
  grid.material = r.correction.labels;
  if (!out.empty())
    io::write_on_ranks(
        comm,
        output_data(std::move(in.data), grid, r.majority, app, cli::input_record(o.in, fr)), in,
        out, o.gather, o.common.write_options(), o.common.memory_limit());
  times.emplace_back("write", t.seconds());
  const cli::Json ranks = cli::ranks_json(comm, in);
  if (comm.rank() != 0) o.common.json.clear();  // rank 0 writes the report
  return finish(app, o, r, fr, fractions, in.shape.dim, in.whole_cells, out, times, ranks);
}

// One process or ranks: the options the flags set, then the run.
int run(const CLI::App& app, Options& o, const dist::Communicator& comm) {
  o.assign.correction.spare_neighbours = !o.paper_order;
  if (comm.rank() == 0) o.assign.correction.progress = cli::terminal_progress(o.common);
  return comm.size() > 1 ? run_assign_on_ranks(app, o, comm) : run_assign(app, o);
}

}  // namespace
}  // namespace hexadapt

int main(int argc, char** argv) {
  CLI::App app("Assign one material per cell (majority, then manifold correction)",
               "hexadapt-assign");
  hexadapt::Options options;
  hexadapt::add_options(app, options);
  return hexadapt::cli::run_on_ranks(
      app, argc, argv, options.common,
      [&](const hexadapt::dist::Communicator& comm) { return hexadapt::run(app, options, comm); });
}
