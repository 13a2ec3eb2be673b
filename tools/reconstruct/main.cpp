// hexadapt-reconstruct: sub-pixel interface reconstruction of an assigned grid (paper
// sec. 4). Reads the grid with its vf_ arrays and `material` array, writes the pixel mesh
// (-o), the geometric model (--model) and a report (--json).
#include <iostream>
#include <string>
#include <variant>

#include "cli.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/rank_files.h"
#include "hexadapt/reconstruct/model_io.h"
#include "hexadapt/reconstruct/pixel_output.h"
#include "hexadapt/reconstruct/reconstruct.h"
#include "ranks.h"

namespace {

using namespace hexadapt;
using reconstruct::Method;

struct Options {
  std::string input, model, model_format = "om";
  cli::InputOptions in;
  bool majority = false;
  bool gather = false;         ///< on ranks: one output file written by rank 0
  std::string cut = "memory";  ///< on ranks: slabs of equal pixel memory, or equal layer counts
  reconstruct::ReconstructOptions lib;
  std::string method = reconstruct::to_string(lib.method);  ///< --method, parsed into lib
  double read_seconds = 0;                                  ///< reading the input, for the report
};

// `block`: the data is one rank's block of the grid.
AssignedGrid read_grid(const io::MeshData& data, const Options& o,
                       const dist::Block* block = nullptr) {
  if (!o.majority && !data.find_cell_array("material"))
    throw InputError(o.input, "",
                     "no `material` cell array: run hexadapt-assign first, or "
                     "pass --majority to use the majority material");
  return io::to_assigned_grid(
      data, o.in.grid(o.majority ? io::MaterialSource::majority : io::MaterialSource::array),
      o.input, nullptr, block);
}

std::string model_stem(std::string path) {
  const std::string ext = ".vtk";
  if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
    path.resize(path.size() - ext.size());
  return path;
}

cli::Json method_json(const reconstruct::ReconstructResult& r, Method m) {
  cli::Json j;
  switch (m) {
    case Method::greedy:
      j["rounds"] = r.greedy.rounds;
      j["fallback_pixels"] = r.greedy.fallback_pixels;
      break;
    case Method::annealing:
      j["attempts"] = r.annealing.attempts;
      j["accepted"] = r.annealing.accepted;
      j["initial_edgecut"] = r.annealing.initial_edgecut;
      j["initial_energy"] = r.annealing.initial_energy;
      j["final_energy"] = r.annealing.final_energy;
      j["time_limited"] = r.annealing.time_limited;
      break;
    case Method::graph_cut:
      j["cycles"] = r.graph_cut.cycles;
      j["initial_energy"] = r.graph_cut.initial_energy;
      j["final_energy"] = r.graph_cut.final_energy;
      break;
    case Method::mip:
      j["variables"] = r.mip.n_variables;
      j["constraints"] = r.mip.n_constraints;
      j["objective"] = r.mip.objective;
      j["best_bound"] = r.mip.best_bound;
      j["solver_seconds"] = r.mip.seconds;
      break;
  }
  return j;
}

// The library's options from the flags, for a grid of dimension `dim`.
void set_options(Options& o, const cli::CommonOptions& common, int dim) {
  auto& lib = o.lib;
  lib.method = reconstruct::parse_method(o.method);
  lib.pixels.max_memory = common.memory_limit();
  lib.pixels.output_bytes_per_pixel = reconstruct::pixel_output_bytes_per_pixel(dim);
  lib.extract_model = !o.model.empty();
  lib.progress = cli::terminal_progress(common);
}

// The pixel mesh as written: its cells, with the provenance and the material names.
io::MeshData output_data(const reconstruct::Reconstruction& rec, const dist::Block& block,
                         const Fractions& f, const CLI::App& app) {
  io::MeshData out = reconstruct::pixel_mesh_data(rec.pixels, block);
  out.metadata = cli::provenance(app);
  io::set_material_names(out, f.names());
  return out;
}

// The report; `write_seconds`: the time the outputs took, after the stage's own phases.
cli::Json report(const CLI::App& app, const Options& o, const reconstruct::Reconstruction& rec,
                 const std::vector<std::string>& files, double write_seconds) {
  const auto& r = rec.result;
  PhaseTimes times{{"read", o.read_seconds}};
  times.insert(times.end(), r.times.begin(), r.times.end());
  times.emplace_back("write", write_seconds);
  const double total = r.discrepancy + r.unpixelated_discrepancy;
  log_info("method " + o.method + " (" + r.status + "): edgecut " + std::to_string(r.edgecut) +
           ", discrepancy " + std::to_string(total));
  cli::Json j = cli::report_header(app);
  j["input"] = o.input;
  j["method"] = o.method;
  j["status"] = r.status;
  j["nsub"] = r.plan.nsub;
  j["pixelated_cells"] = r.plan.n_blocks;
  j["mixed_cells"] = r.plan.n_free_blocks;
  j["pixels"] = r.plan.n_pixels;
  j["free_pixels"] = r.plan.n_free_pixels;
  j["memory_estimate_bytes"] = r.plan.bytes;
  j["edgecut"] = r.edgecut;
  j["discrepancy"] = total;
  j["discrepancy_pixelated"] = r.discrepancy;
  j["discrepancy_unpixelated"] = r.unpixelated_discrepancy;
  j["relative_discrepancy"] = r.relative_discrepancy;
  j["method_stats"] = method_json(r, o.lib.method);
  if (!o.model.empty()) {
    j["model"] = {{"points", rec.model.points.size()},
                  {"facets", rec.model.facets.size()},
                  {"curves", rec.model.curves.size()},
                  {"corners", rec.model.corners.size()}};
  }
  j["files"] = files;
  j["exit_code"] = cli::ok;
  j["times"] = cli::phase_times_json(times);
  return j;
}

template <class M>
int run(const M& mesh, const Fractions& f, const CellMaterials& assignment, Options& o,
        const cli::CommonOptions& common, const CLI::App& app) {
  set_options(o, common, M::dim);
  auto& lib = o.lib;
  if (!common.quiet) {
    // The estimate is shown before anything big is allocated (the build refuses beyond
    // --max-memory).
    auto po = lib.pixels;
    const auto plan = reconstruct::plan_pixels(mesh, f, assignment, po);
    std::cerr << app.get_name() << ": " << plan.n_pixels << " pixels (" << plan.n_free_pixels
              << " free) in " << plan.n_blocks << " cells, nsub " << plan.nsub
              << "; pixel memory estimate " << plan.bytes / 1e6 << " MB plus the " << o.method
              << " working arrays\n";
  }
  const auto rec = reconstruct::reconstruct(mesh, f, assignment, lib);
  const auto& r = rec.result;
  Timer t;
  io::write_mesh(output_data(rec, dist::Block::whole(mesh.n_cells(), mesh.n_nodes()), f, app),
                 common.output, common.write_options());
  std::vector<std::string> files{common.output};
  if (!o.model.empty()) {
    const std::string stem = model_stem(o.model);
    reconstruct::write_model_vtk(rec.model, f.names(), stem + ".vtk");
    files.push_back(stem + ".vtk");
    if (M::dim == 3)
      for (const auto& p :
           reconstruct::write_model_openmesh(rec.model, f.names(), stem, o.model_format))
        files.push_back(p);
  }
  cli::write_report(common, report(app, o, rec, files, t.seconds()));
  if (lib.method == Method::mip && r.mip.status == reconstruct::MipStatus::timed_out_no_solution)
    log_warning(
        "the MIP found no solution within the time limit: the pixels keep the "
        "largest-remainder fill");
  return cli::ok;
}

void add_options(CLI::App& app, Options& o, cli::CommonOptions& common) {
  auto& lib = o.lib;
  app.add_option("input", o.input, "Assigned grid (vf_ arrays and a `material` cell array)")
      ->required();
  cli::add_common_options(app, common);
  cli::add_write_options(app, common);
  app.add_option("--model", o.model,
                 "Write the geometric model: OUT.vtk, and in 3D OUT.<a>-<b>.om");
  app.add_option("--model-format", o.model_format, "OpenMesh format of the 3D surfaces")
      ->check(CLI::IsMember({"om", "obj"}))
      ->capture_default_str();
  app.add_option("--method", o.method, "greedy, annealing, graphcut or mip")
      ->check(CLI::IsMember({"greedy", "annealing", "graphcut", "mip"}))
      ->capture_default_str();
  app.add_option("--nsub", lib.pixels.nsub, "Pixels per axis and cell (0: 10 in 2D, 4 in 3D)")
      ->capture_default_str();
  cli::add_input_options(app, o.in);
  app.add_flag("--majority", o.majority, "Use the majority material instead of a `material` array");
  app.add_option("--iterations", lib.annealing.iterations,
                 "Annealing: swap attempts (0: 200 per free pixel)")
      ->capture_default_str();
  app.add_option("--time-budget", lib.annealing.time_budget,
                 "Annealing: run this many seconds instead (not reproducible)")
      ->capture_default_str();
  app.add_option("--seed", lib.annealing.seed, "Annealing / MIP fill: random seed")
      ->capture_default_str();
  app.add_option("--lambda", lib.graph_cut.lambda, "Graph cut: weight of the data term")
      ->capture_default_str();
  app.add_option("--beta", lib.graph_cut.beta, "Graph cut: weight of the smoothness term")
      ->capture_default_str();
  app.add_option("--time-limit", lib.mip.time_limit, "MIP: seconds given to GLPK")
      ->capture_default_str();
  app.add_flag("--gather", o.gather,
               "Under mpirun on several ranks: write one file of the whole pixel mesh (any "
               "format) instead of a .vtu piece per rank and the .pvtu naming them");
  app.add_option("--cut", o.cut,
                 "Under mpirun on several ranks, how the grid is cut into slabs: 'memory' reads "
                 "it once more first to give each rank an equal share of the pixels' memory; "
                 "'layers' gives each the same number of layers and reads the grid once "
                 "(faster, balanced when the interface spreads evenly across the layers)")
      ->check(CLI::IsMember({"memory", "layers"}))
      ->capture_default_str();
}

// Reads the assigned grid and reconstructs it.
int run_reconstruct(const CLI::App& app, Options& o, const cli::CommonOptions& common) {
  o.lib.mip.seed = o.lib.annealing.seed;
  cli::check_files({{"input", o.input}},
                   {{"-o", common.output, true, true},
                    {"--model", o.model.empty() ? "" : model_stem(o.model) + ".vtk"},
                    {"--json", common.json}});
  const Timer read;
  io::MeshData data = io::read_mesh(o.input, o.in.read_options());
  const AssignedGrid grid = read_grid(data, o);
  o.read_seconds = read.seconds();
  return std::visit(
      [&](const auto& m) { return run(m, grid.fractions, grid.material, o, common, app); },
      grid.mesh);
}

// The bytes each layer of the grid needs on a rank: the grid's own per cell and the pixels'
// share (owned_cell_bytes), from `in` read with one ghost layer at least.
std::vector<double> layer_bytes(const Options& o, const dist::Communicator& comm,
                                const io::RankInput& in) {
  std::vector<double> owned;
  dist::on_every_rank(comm, [&] {
    const AssignedGrid grid = read_grid(in.data, o, &in.slab.block);
    owned = std::visit(
        [&](const auto& m) {
          return reconstruct::owned_cell_bytes(m, grid.fractions, grid.material, o.lib.pixels,
                                               in.slab.block);
        },
        grid.mesh);
  });
  for (double& b : owned) b += cli::reconstruct_grid_bytes_per_cell;
  return dist::layer_sums(comm, in.slab, owned);
}

// The bytes each cell of a part of an unstructured mesh needs (the grid's own and its
// pixels'), for PT-Scotch to balance: the pixels of the cells beside the part's border are
// counted as the part alone shows them.
std::vector<double> cell_bytes(const Options& o, const io::MeshPart& part) {
  const dist::Block block = dist::Block::listed(part.cell_ids, part.data.n_cells(), part.node_ids,
                                                std::vector<char>(part.node_ids.size(), 1));
  const AssignedGrid grid = read_grid(part.data, o, &block);
  std::vector<double> bytes = std::visit(
      [&](const auto& m) {
        return reconstruct::owned_cell_bytes(m, grid.fractions, grid.material, o.lib.pixels, block);
      },
      grid.mesh);
  for (double& b : bytes) b += cli::reconstruct_part_bytes_per_cell;
  return bytes;
}

// On the ranks of an MPI job: each rank reads its slab of the grid with the ghost layers
// greedy needs, pixelates it and writes the pixels of the cells it owns. With --cut memory
// the grid is first read cut by layer counts to weigh its layers (the pixels follow the mixed
// cells), and the slabs are cut by those weights.
int run_reconstruct_on_ranks(const CLI::App& app, Options& o, cli::CommonOptions& common,
                             const dist::Communicator& comm) {
  dist::on_every_rank(comm, [&] {
    cli::check_files({{"input", o.input}},
                     {{"-o", common.output, true, true}, {"--json", common.json}});
    cli::check_rank_output("-o", common.output, o.gather, false);
    if (!o.model.empty())
      throw OptionError("--model: the geometric model of the whole grid is built on one process");
    if (o.method != reconstruct::to_string(Method::greedy))
      throw OptionError("--method " + o.method + " runs on one process: on several ranks, greedy");
  });
  const Timer read;
  const int nsub = o.lib.pixels.nsub
                       ? o.lib.pixels.nsub
                       : std::min(reconstruct::default_nsub(2), reconstruct::default_nsub(3));
  // The labels of the whole grid and the options that depend on its dimension.
  const auto prepare = [&](const io::RankInput& first) {
    if (!o.in.fractions.labels.empty())
      o.in.fractions.label_values = cli::grid_labels(comm, o.in, o.input, first);
    set_options(o, common, first.shape.dim);
  };
  // An unstructured mesh is cut by PT-Scotch, its cells weighed by their bytes (a label map's
  // cells are pure: all alike).
  std::vector<double> weights;
  io::CellWeights cell_weights;
  if (o.cut == "memory" && o.in.fractions.labels.empty())
    cell_weights = [&](const io::MeshPart& part) {
      set_options(o, common, part.data.dim);
      return cell_bytes(o, part);
    };
  if (o.cut == "memory" && !io::holds_unstructured_mesh(o.input)) {
    const io::RankInput probe = io::read_on_ranks(comm, o.input, o.in.read_options(), 1);
    prepare(probe);
    weights = layer_bytes(o, comm, probe);
  }
  io::RankInput in = io::read_mesh_on_ranks(comm, o.input, o.in.read_options(),
                                              reconstruct::greedy_ghost_layers(nsub, o.lib.greedy),
                                              weights, cell_weights);
  if (weights.empty()) prepare(in);
  AssignedGrid grid;
  dist::on_every_rank(comm, [&] {
    grid = read_grid(in.data, o, &in.slab.block);
    std::visit(
        [&](const auto& m) {
          reconstruct::check_pixel_memory(
              reconstruct::plan_pixels(m, grid.fractions, grid.material, o.lib.pixels),
              o.lib.pixels);
        },
        grid.mesh);
  });
  o.read_seconds = read.seconds();
  if (comm.rank() != 0) o.lib.progress = nullptr;
  const dist::Distribution where{comm, in.slab.block};
  const auto rec = std::visit(
      [&](const auto& m) {
        return reconstruct::reconstruct(m, grid.fractions, grid.material, o.lib, where);
      },
      grid.mesh);
  Timer t;
  io::write_disjoint_pieces(comm, output_data(rec, in.slab.block, grid.fractions, app),
                             common.output, o.gather, common.write_options(), common.memory_limit(),
                             in.structured ? "" : "parent");
  cli::Json j = report(app, o, rec, {common.output}, t.seconds());
  j["ranks"] = cli::ranks_json(comm, in);
  if (comm.rank() != 0) common.json.clear();  // rank 0 writes the report
  cli::write_report(common, j);
  return cli::ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Sub-pixel interface reconstruction and geometric model (paper sec. 4)",
               "hexadapt-reconstruct"};
  Options o;
  cli::CommonOptions common;
  add_options(app, o, common);
  return cli::run_on_ranks(app, argc, argv, common, [&](const dist::Communicator& comm) {
    return comm.size() > 1 ? run_reconstruct_on_ranks(app, o, common, comm)
                           : run_reconstruct(app, o, common);
  });
}
