// hexadapt-measure: measures any quad / hex mesh file (DESIGN sec. 2): quality statistics
// and histogram, cells below the threshold, the mesh check, purity, node-to-target
// distances, cell sizes and, with --reference, the discrepancy of paper eq. 5 and the
// volume per material. Exit 3 when the threshold, the mesh check, the min-edge criterion or
// --max-volume-error is not met. Report fields: docs/reports.md.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "cli.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/mesh_part.h"
#include "hexadapt/io/rank_files.h"
#include "hexadapt/io/vtk_collection.h"
#include "hexadapt/measure/discrepancy.h"
#include "hexadapt/measure/imprint.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/measure/size_report.h"
#include "hexadapt/measure/target_distance.h"
#include "input_record.h"
#include "memory.h"
#include "ranks.h"

namespace {

using namespace hexadapt;

struct Args {
  std::string input;
  std::string quality_field;
  std::string reference;
  std::string discrepancy_field;
  std::string target_array = "target";
  cli::InputOptions in;  ///< --plane, and how the reference fractions are read
  QualityReportOptions report;
  SizeReportOptions size;
  DiscrepancyOptions volume;
};

void add_options(CLI::App& app, Args& a) {
  app.add_option("mesh", a.input,
                 "Mesh file to measure (.vtu .vtk .vti .vtr .vts .pvtu .pvtr .pvts .vtm .pvd "
                 ".txt .exo)")
      ->required();
  app.add_option("--threshold", a.report.threshold,
                 "Minimum scaled Jacobian every cell must reach (exit 3 otherwise)")
      ->capture_default_str()
      ->check(CLI::Range(-1.0, 1.0));
  app.add_option("--bins", a.report.bins, "Number of histogram bins over [-1, 1]")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  app.add_option("--quality-field", a.quality_field,
                 "Write the mesh with per-cell 'scaled_jacobian' and 'shape' arrays to this "
                 "file (.vtu or .vtk)");
  app.add_option("--list", a.report.max_listed,
                 "How many offending cells / nodes of each kind the report lists")
      ->capture_default_str()
      ->check(cli::non_negative);
  app.add_option("--duplicate-tolerance", a.report.check.duplicate_tolerance,
                 "Nodes closer than this times the bounding-box diagonal are duplicates")
      ->capture_default_str()
      ->check(cli::non_negative);
  app.add_option("--conformity-tolerance", a.report.check.conformity_tolerance,
                 "A node within this times a boundary face's diameter of the face hangs on it")
      ->capture_default_str()
      ->check(cli::non_negative);
  app.add_option("--material-array", a.report.material_array,
                 "Cell array of material indices checked for purity")
      ->capture_default_str();
  app.add_option("--reference", a.reference,
                 "Input grid with vf_* fraction arrays: imprint the mesh's materials onto it and "
                 "report the discrepancy (paper eq. 5) and the volume per material");
  app.add_option("--discrepancy-field", a.discrepancy_field,
                 "Write the reference grid with a per-cell 'discrepancy' array to this file "
                 "(.vtu or .vtk; needs --reference)");
  app.add_option("--target-array", a.target_array,
                 "Point array (3 components) of node targets for the distances")
      ->capture_default_str();
  app.add_option("--min-edge", a.size.min_edge,
                 "Every cell's shortest edge must be at least this times its local input size "
                 "(the 'local_size' cell array, or the mean edge of the --reference cell holding "
                 "its centroid); 0: not checked")
      ->capture_default_str()
      ->check(cli::non_negative);
  app.add_option("--max-volume-error", a.volume.max_volume_error,
                 "Every material's volume must be within this share of its input volume "
                 "(needs --reference; default: not checked)")
      ->check(cli::non_negative);
  cli::add_input_options(app, a.in);
}

// Library errors about the data name no file: add the input's name.
[[noreturn]] void rethrow_with_file(const InputError& e, const std::string& file) {
  if (!e.file().empty()) throw e;
  throw InputError(file, e.where(), e.message());
}

void print_summary(const std::string& file, const QualityReport& r) {
  std::printf("%s: %d cells, %d nodes (%s)\n", file.c_str(), r.n_cells, r.n_nodes,
              r.dim == 3 ? "hexes" : "quads");
  std::printf("  scaled Jacobian  min %.6f  mean %.6f  max %.6f\n", r.scaled_jacobian.min,
              r.scaled_jacobian.mean, r.scaled_jacobian.max);
  std::printf("  shape            min %.6f  mean %.6f  max %.6f\n", r.shape.min, r.shape.mean,
              r.shape.max);
  std::printf("  below threshold %.3g: %d cells%s\n", r.threshold, r.below_threshold,
              r.quality_ok() ? "" : "  FAILED");
  if (!r.topology_error.empty()) {
    std::printf("  mesh check: FAILED: %s\n", r.topology_error.c_str());
  } else {
    const auto& c = r.check;
    std::printf(
        "  mesh check: %s  (hanging nodes %d, duplicate nodes %d, unreferenced nodes %d, "
        "inverted cells %d, non-manifold nodes %d)\n",
        c.ok() ? "ok" : "FAILED", c.hanging_nodes, c.duplicate_nodes, c.unreferenced_nodes,
        c.inverted_cells, c.nonmanifold_nodes);
  }
  const auto& p = r.purity;
  if (p.has_material)
    std::printf("  purity: %d cells with an invalid material index\n", p.invalid_material_cells);
  if (!p.fraction_arrays.empty())
    std::printf("  fractions: %zu arrays, %d mixed cells\n", p.fraction_arrays.size(),
                p.mixed_cells);
}

void write_quality_field(const CLI::App& app, const io::MeshData& data, const std::string& path,
                         const io::WriteOptions& options) {
  const CellQualities q = cell_qualities(data);
  io::MeshData out = data;
  for (auto [name, values] :
       {std::pair{"scaled_jacobian", &q.scaled_jacobian}, std::pair{"shape", &q.shape}}) {
    io::DataArray a;
    a.name = name;
    a.values = *values;
    out.set_cell_array(std::move(a));
  }
  for (const auto& kv : cli::provenance(app)) out.metadata.push_back(kv);
  io::write_mesh(out, path, options);
}

struct DiscrepancyRun {
  io::MeshData reference;
  DiscrepancyReport report;
};

// Imprints the mesh's materials onto the reference grid; material m of the mesh is the
// reference's m-th fraction array.
DiscrepancyRun measure_discrepancy(const Args& a, const cli::InputOptions& reading,
                                   const io::MeshData& mesh, const Progress& bar, PhaseTimes& times,
                                   double memory_limit) {
  DiscrepancyRun run;
  run.reference = cli::timed_phase(times, bar, "read_reference", [&] {
    return io::read_mesh(a.reference, reading.read_options());
  });
  if (!a.discrepancy_field.empty())
    io::check_mesh_output(a.discrepancy_field, run.reference.is_structured());
  const index_t cells = mesh.n_cells() + run.reference.n_cells();
  cli::check_memory("measuring " + std::to_string(cells) + " cells of mesh and reference",
                    static_cast<double>(cells) * cli::measure_bytes_per_cell, memory_limit);
  const Fractions fractions =
      io::to_assigned_grid(run.reference, reading.grid(io::MaterialSource::none), a.reference)
          .fractions;
  const CellMaterials materials =
      io::read_material_array(mesh, fractions.n_materials(), a.input, a.report.material_array);
  Timer timer;
  Imprint im;
  ImprintOptions options;
  options.progress = bar;
  try {
    im = imprint(run.reference, mesh, materials, fractions.n_materials(), options);
  } catch (const InputError& e) {
    rethrow_with_file(e, a.input);
  }
  times.emplace_back("imprint", timer.seconds());
  timer.restart();
  run.report = discrepancy(im, fractions, a.volume);
  times.emplace_back("discrepancy", timer.seconds());
  return run;
}

void write_discrepancy_field(const CLI::App& app, DiscrepancyRun& run, const std::string& path,
                             const io::WriteOptions& options) {
  io::DataArray d;
  d.name = "discrepancy";
  d.values = run.report.per_cell;
  run.reference.set_cell_array(std::move(d));
  for (const auto& kv : cli::provenance(app)) run.reference.metadata.push_back(kv);
  io::write_mesh(run.reference, path, options);
}

void print_discrepancy(const DiscrepancyReport& d) {
  std::printf("  discrepancy  total %.6g  relative %.6g  max per cell %.6g (cell %d)\n",
              d.in_grid_units(d.total), d.relative, d.in_grid_units(d.max_cell),
              d.max_cell_id.value());
  for (const auto& m : d.materials)
    std::printf("  volume %-12s input %.9g  output %.9g  imprinted %.9g  error %+.3g%s\n",
                m.name.c_str(), d.in_grid_units(m.input), d.in_grid_units(m.output),
                d.in_grid_units(m.imprinted), m.volume_error(),
                std::abs(m.volume_error()) > d.max_volume_error ? "  FAILED" : "");
}

void print_size(const SizeReport& s) {
  const auto& f = s.mesh;
  std::printf("  size  edge ratio min %.4g  mean %.4g  max %.4g  time step min %.6g (cell %d)",
              f.edge_ratio.min, f.edge_ratio.mean, f.edge_ratio.max, f.time_step.min,
              f.time_step_min_cell.value());
  if (s.has_reference) std::printf("  %.4g x the input's", s.time_step_ratio);
  std::printf("\n");
  if (!s.checked()) {
    std::printf("  min edge: not checked (%s)\n", s.not_checked.c_str());
    return;
  }
  std::printf(
      "  min edge %.3g x local size (%s): shortest edge / local size min %.4g, %d cells "
      "below%s\n",
      s.min_edge, s.local_size == LocalSizeSource::array ? "local_size array" : "reference",
      f.min_relative_edge, f.below_min_edge, s.passed() ? "" : "  FAILED");
}

// What measure found, in the report's sections.
struct Measured {
  QualityReport report;
  TargetDistances distances;
  SizeReport size;
  DiscrepancyReport discrepancy;              ///< with --reference
  std::optional<cli::InputOptions> recorded;  ///< how the reference was read
};

// Writes the JSON report (with a `ranks` block when `ranks` is not null), prints the summary
// and returns the exit code.
int finish(const CLI::App& app, const cli::CommonOptions& common, const Args& a, const Measured& m,
           const PhaseTimes& times, const cli::Json& ranks) {
  const bool passed =
      m.report.passed() && m.size.passed() && (a.reference.empty() || m.discrepancy.passed());
  const int code = passed ? cli::ok : cli::target_missed;
  cli::Json json = cli::report_header(app);
  json["input"] = a.input;
  const cli::Json sections = cli::Json::parse(quality_report_json(m.report));
  for (const auto& [key, value] : sections.items()) {
    if (key == "passed") {
      json["distances"] = cli::Json::parse(target_distances_json(m.distances));
      if (!a.reference.empty()) {
        json["reference"] = a.reference;
        json["reference_read_with"] = m.recorded ? "the record in the input" : "the flags";
        json["discrepancy"] = cli::Json::parse(discrepancy_json(m.discrepancy));
      }
      json["size"] = cli::Json::parse(size_report_json(m.size));
      json[key] = passed;
    } else {
      json[key] = value;
    }
  }
  json["exit_code"] = code;
  json["times"] = cli::phase_times_json(times);
  if (!ranks.is_null()) json["ranks"] = ranks;
  cli::write_report(common, json);
  if (!common.quiet) {
    print_summary(a.input, m.report);
    if (m.distances.has_targets)
      std::printf("  distances to targets: dist %.6g  max %.6g  (%d nodes)\n", m.distances.sum,
                  m.distances.max, m.distances.nodes);
    if (!a.reference.empty()) print_discrepancy(m.discrepancy);
    print_size(m.size);
  }
  return code;
}

int measure(const CLI::App& app, const cli::CommonOptions& common, const Args& a) {
  if (app.count("--max-volume-error") > 0 && a.reference.empty())
    throw OptionError("--max-volume-error needs --reference (the input volumes)");
  if (!a.discrepancy_field.empty()) {
    if (a.reference.empty())
      throw OptionError("--discrepancy-field needs --reference (the grid the field lives on)");
  }
  cli::check_files({{"input", a.input}, {"--reference", a.reference}},
                   {{"--quality-field", a.quality_field, true},
                    {"--discrepancy-field", a.discrepancy_field, true},
                    {"--json", common.json}});
  PhaseTimes times;
  const Progress bar = cli::terminal_progress(common);
  const io::MeshData data = cli::timed_phase(
      times, bar, "read", [&] { return io::read_mesh(a.input, a.in.read_options()); });
  if (!a.quality_field.empty()) io::check_mesh_output(a.quality_field, data.is_structured());
  cli::check_memory("measuring " + std::to_string(data.n_cells()) + " cells",
                    static_cast<double>(data.n_cells()) * cli::measure_bytes_per_cell,
                    common.memory_limit());
  Timer timer;
  QualityReport report;
  try {
    QualityReportOptions options = a.report;
    options.progress = bar;
    report = quality_report(data, options);
  } catch (const InputError& e) {
    rethrow_with_file(e, a.input);
  }
  TargetDistances distances;
  try {
    distances = target_distances(data, a.target_array);
  } catch (const InputError& e) {
    rethrow_with_file(e, a.input);
  }
  times.emplace_back("quality", timer.seconds());
  DiscrepancyRun disc;
  // The reference is read as the input was when no reading flag says otherwise.
  const std::optional<cli::InputOptions> recorded =
      cli::input_options_given(app) ? std::nullopt : cli::carried_input(data, a.input);
  if (!a.reference.empty())
    disc = measure_discrepancy(a, recorded.value_or(a.in), data, bar, times, common.memory_limit());
  timer.restart();
  SizeReport size;
  try {
    SizeReportOptions options = a.size;
    options.max_listed = a.report.max_listed;
    options.progress = bar;
    size = size_report(data, a.reference.empty() ? nullptr : &disc.reference, options);
  } catch (const InputError& e) {
    rethrow_with_file(e, a.input);
  }
  times.emplace_back("size", timer.seconds());
  if (!a.discrepancy_field.empty())
    cli::timed_phase(times, bar, "write_discrepancy", [&] {
      write_discrepancy_field(app, disc, a.discrepancy_field, common.write_options());
      return 0;
    });
  if (!a.quality_field.empty())
    cli::timed_phase(times, bar, "write_quality", [&] {
      write_quality_field(app, data, a.quality_field, common.write_options());
      return 0;
    });
  return finish(app, common, a, {report, distances, size, disc.report, recorded}, times, {});
}

// On the ranks of an MPI job: rank r reads its share of the .pvtu's pieces (a single file:
// rank 0 reads it); the pieces are
// merged on the ranks (the mesh one process reads), each rank's cells get a ghost layer, and
// the reports are those of the whole mesh (ids global; measure/quality_report.h).
int measure_on_ranks(const CLI::App& app, const cli::CommonOptions& common, const Args& a,
                     const dist::Communicator& comm) {
  dist::on_every_rank(comm, [&] {
    for (const auto& [flag, value] :
         {std::pair{"--reference", a.reference}, std::pair{"--quality-field", a.quality_field},
          std::pair{"--discrepancy-field", a.discrepancy_field}})
      if (!value.empty())
        throw OptionError(std::string(flag) + " runs on one process, not on the " +
                          std::to_string(comm.size()) + " ranks of this MPI job");
    if (app.count("--max-volume-error") > 0)
      throw OptionError("--max-volume-error needs --reference (the input volumes)");
    cli::check_files({{"input", a.input}}, {{"--json", common.json}});
  });
  PhaseTimes times;
  const Timer timer;
  const io::ReadOptions reading = a.in.read_options();
  io::RankPieces pieces = io::read_pieces_on_ranks(comm, a.input, reading);
  // Each step whole inside on_every_rank: a rank that fails alone must not leave the others
  // waiting in a collective it skipped.
  io::MeshPart merged;
  dist::on_every_rank(comm,
                     [&] { merged = io::merge_rank_pieces(comm, std::move(pieces), reading); });
  dist::on_every_rank(comm, [&] {
    cli::check_memory("measuring " + std::to_string(merged.data.n_cells()) + " cells on rank " +
                          std::to_string(comm.rank()),
                      static_cast<double>(merged.data.n_cells()) * cli::measure_bytes_per_cell,
                      common.memory_limit());
  });
  const io::GhostedPart part = io::with_ghost_layers(comm, merged);
  merged = io::MeshPart();
  times.emplace_back("read", timer.seconds());
  Measured m;
  Timer phase;
  dist::on_every_rank(comm, [&] {
    try {
      m.report = quality_report(comm, part, a.report);
      m.distances = target_distances(comm, part, a.target_array);
    } catch (const InputError& e) {
      rethrow_with_file(e, a.input);
    }
  });
  times.emplace_back("quality", phase.seconds());
  phase.restart();
  dist::on_every_rank(comm, [&] {
    SizeReportOptions options = a.size;
    options.max_listed = a.report.max_listed;
    try {
      m.size = size_report(comm, part, options);
    } catch (const InputError& e) {
      rethrow_with_file(e, a.input);
    }
  });
  times.emplace_back("size", phase.seconds());
  cli::Json ranks = {
      {"count", comm.size()},
      {"cells", dist::all_gather_values(comm, std::vector<std::int64_t>{part.owned_cells})},
      {"ghost_cells",
       dist::all_gather_values(
           comm, std::vector<std::int64_t>{part.part.data.n_cells() - part.owned_cells})},
      {"bytes_sent", dist::all_gather_values(comm, std::vector<std::uint64_t>{comm.bytes_sent()})},
      {"peak_memory",
       dist::all_gather_values(comm, std::vector<std::uint64_t>{cli::peak_resident_bytes()})}};
  cli::CommonOptions out = common;
  if (comm.rank() != 0) {  // rank 0 writes the report and prints
    out.json.clear();
    out.quiet = true;
  }
  return finish(app, out, a, m, times, ranks);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Measure a quad or hex mesh: quality (scaled Jacobian, shape), histogram, mesh "
      "check (conformity, duplicate / unreferenced nodes, inverted cells, "
      "manifoldness), purity, distances to node targets, cell sizes (edge ratio, "
      "time-step length, shortest edge against the local input size) and, with "
      "--reference, the discrepancy and the volume per material against the input "
      "fractions. Exit codes: 0 passed, 1 usage, 2 bad input, 3 threshold, mesh check, "
      "--min-edge or --max-volume-error not met, 4 internal error.",
      "hexadapt-measure");
  cli::CommonOptions common;
  Args args;
  add_options(app, args);
  cli::add_common_options(app, common, /*with_output=*/false);
  cli::add_write_options(app, common);
  return cli::run_on_ranks(app, argc, argv, common, [&](const dist::Communicator& comm) {
    return comm.size() > 1 ? measure_on_ranks(app, common, args, comm) : measure(app, common, args);
  });
}
