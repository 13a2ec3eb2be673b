// hexadapt-adapt: moves the interface nodes of an assigned grid onto the material interfaces
// and pillows, giving a conformal mesh whose cells each hold one material (paper sec. 5).
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli.h"
#include "hexadapt/adapt/adapt.h"
#include "hexadapt/adapt/adapt_io.h"
#include "hexadapt/adapt/adapt_on_ranks.h"
#include "hexadapt/adapt/adapt_report.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/rank_files.h"
#include "hexadapt/reconstruct/model_io.h"
#include "input_record.h"
#include "memory.h"
#include "ranks.h"

namespace {

using namespace hexadapt;
using cli::Json;

// The flags set the library's options directly: their defaults are AdaptOptions' own.
struct Args {
  std::string input;
  AdaptOptions options;
  std::string method = to_string(AdaptOptions{}.method);
  std::string layers = to_string(AdaptOptions{}.layers);
  std::string model;
  cli::InputOptions in;
  bool gather = false;  ///< on ranks: one output file written by rank 0
};

// One line per failing cell, worst first, for stderr.
std::string failures_text(const std::vector<CellFailure>& failures, double threshold) {
  std::string text;
  for (const CellFailure& f : failures) {
    char line[256];
    if (f.size_failed())
      std::snprintf(line, sizeof line,
                    "\n  cell %d at (%.6g, %.6g, %.6g): shortest edge %.6g < %.6g (min_edge)",
                    f.cell.value(), f.centroid.x(), f.centroid.y(), f.centroid.z(), f.shortest_edge,
                    f.min_length);
    else
      std::snprintf(line, sizeof line,
                    "\n  cell %d at (%.6g, %.6g, %.6g): scaled Jacobian %.6g < %.6g (threshold)",
                    f.cell.value(), f.centroid.x(), f.centroid.y(), f.centroid.z(),
                    f.scaled_jacobian, threshold);
    text += line;
  }
  return text;
}

// The reconstruction's model (hexadapt-reconstruct --model), its materials checked against
// the grid's.
reconstruct::ModelFile read_model(const std::string& path, const std::vector<std::string>& names) {
  reconstruct::ModelFile m = reconstruct::read_model_vtk(path);
  if (m.materials != names) {
    std::string want, got;
    for (const auto& n : names) want += " " + n;
    for (const auto& n : m.materials) got += " " + n;
    throw InputError(path, "title line",
                     "the model's materials (" + got + " ) are not the grid's (" + want + " )");
  }
  return m;
}

// Nodes that stay away from their interface are said even when the run succeeds: how many,
// their share, the farthest, and how many of them the cuts between ranks held.
void warn_blocked(const AdaptFigures& f, double near) {
  if (f.blocked == 0 || !f.farthest.valid) return;
  const Vec3& p = f.farthest.position;
  const std::string node = f.farthest.node >= 0 ? "node " + std::to_string(f.farthest.node) + " "
                                                : std::string();
  char text[512];
  std::snprintf(text, sizeof text,
                "%d of %d interface nodes (%.1f%%) stay farther than %g local sizes from their "
                "interface; the farthest, %sat (%.6g, %.6g, %.6g), by %.4g (%.3g local "
                "sizes): see the 'blocked' and 'surface_distance' point arrays",
                f.blocked, f.interface_nodes, 100.0 * f.blocked / f.interface_nodes, near,
                node.c_str(), p.x(), p.y(), p.z(), f.farthest.distance,
                f.farthest.local_size > 0 ? f.farthest.distance / f.farthest.local_size : 0.0);
  std::string line = text;
  if (f.frozen_blocked > 0)
    line += "; " + std::to_string(f.frozen_blocked) + " of them held on the cuts between ranks";
  log_warning(line);
}

// -v: each step of the pipeline, then where the interface nodes ended.
template <class M>
void log_steps(const AdaptResult<M>& r, double near) {
  char text[256];
  for (const AdaptStep& s : r.steps) {
    std::snprintf(text, sizeof text, "step %-12s %8.2f s  %9d cells  min scaled Jacobian %.4f",
                  s.name.c_str(), s.seconds, s.cells, s.min_quality);
    log_info(text);
  }
  std::snprintf(text, sizeof text,
                "%d interface nodes: %d on their target, %d within %g local sizes of their "
                "interface, %d blocked; %d cells, min scaled Jacobian %.4f, shortest edge %.3g "
                "local sizes",
                r.n_interface_nodes, r.n_reached, r.n_near_interface, near, r.n_blocked,
                r.mesh.n_cells(), r.min_quality, r.min_edge_ratio);
  log_info(text);
}

// The guaranteed method does not start from cells already failing a criterion: name them.
// `bad`: their ids, increasing; `worst`: the worst of them.
int refuse_bad_input(const cli::CommonOptions& common, Json& report, const PhaseTimes& times,
                     const std::vector<std::int64_t>& bad, const std::vector<CellFailure>& worst,
                     double threshold) {
  log_warning(std::to_string(bad.size()) + " input cells fail the threshold " +
              std::to_string(threshold) +
              " or the size criterion (--min-edge); the worst:" + failures_text(worst, threshold) +
              "\nnothing written (--allow-bad-input runs anyway, without the guarantee; "
              "--min-edge 0 drops the size criterion)");
  report["bad_input_cells"] = bad;
  report["threshold_met"] = false;
  report["exit_code"] = cli::target_missed;
  report["times"] = cli::phase_times_json(times);
  cli::write_report(common, report);
  return cli::target_missed;
}

// The report's last fields and the warnings of a run that wrote its mesh; its exit code.
int finish(const cli::CommonOptions& common, Json& report, const PhaseTimes& times,
           const AdaptOptions& options, const AdaptFigures& figures,
           const std::vector<CellFailure>& worst) {
  const index_t below = figures.failing();
  report["threshold_met"] = below == 0;
  report["exit_code"] = below == 0 ? cli::ok : cli::target_missed;
  report["times"] = cli::phase_times_json(times);
  cli::write_report(common, report);
  warn_blocked(figures, options.near_interface);
  if (below == 0) return cli::ok;
  log_warning(std::to_string(below) + " output cells fail the threshold " +
              std::to_string(options.threshold) + " or the size criterion" +
              (options.method == AdaptMethod::base ? " (the base method gives no guarantee)" : "") +
              "; the worst:" + failures_text(worst, options.threshold) + "\nmesh written to " +
              common.output);
  return cli::target_missed;
}

// The report's first fields: the run's input, output and options.
Json report_start(const CLI::App& app, const Args& args, const cli::CommonOptions& common,
                  const AdaptOptions& options, const std::vector<std::string>& materials) {
  Json report = cli::report_header(app);
  report["input"] = args.input;
  report["output"] = common.output;
  report["method"] = to_string(options.method);
  report["threshold"] = options.threshold;
  report["min_edge"] = options.min_edge;
  report["layers"] = to_string(options.layers);
  report["steps"] = options.move.steps;
  report["drag"] = options.move.drag;
  report["materials"] = materials;
  report["model"] = args.model;
  return report;
}

// The library's options from the flags.
AdaptOptions adapt_options(const Args& args, const cli::CommonOptions& common) {
  AdaptOptions options = args.options;
  options.method = parse_adapt_method(args.method);
  options.layers = parse_layer_strategy(args.layers);
  options.progress = cli::terminal_progress(common);
  return options;
}

// The metadata of `data` (its record of how it was read); its cells and arrays released.
io::MeshData metadata_only(io::MeshData& data) {
  io::MeshData out;
  out.metadata = std::move(data.metadata);
  data = io::MeshData();
  return out;
}

// The output's provenance and the input's record.
void record_provenance(const CLI::App& app, const io::MeshData& input, io::MeshData& out) {
  for (auto& kv : cli::provenance(app)) out.metadata.push_back(kv);
  cli::pass_input_record(input, out);
}

int run_adapt(const CLI::App& app, const Args& args, const cli::CommonOptions& common) {
  cli::check_files({{"input", args.input}, {"--model", args.model}},
                   {{"-o", common.output, true, true}, {"--json", common.json}});
  const AdaptOptions options = adapt_options(args, common);
  Timer clock;
  PhaseTimes times;
  io::MeshData in = io::read_mesh(args.input, args.in.read_options());
  cli::check_memory("adapting " + std::to_string(in.n_cells()) + " cells",
                    static_cast<double>(in.n_cells()) * cli::adapt_bytes_per_cell,
                    common.memory_limit());
  AssignedGrid grid =
      io::to_assigned_grid(in, args.in.grid(io::MaterialSource::array), args.input);
  const io::MeshData input = metadata_only(in);
  reconstruct::ModelFile model;
  if (!args.model.empty()) model = read_model(args.model, grid.names());
  times.emplace_back("read", clock.seconds());
  clock.restart();

  const std::vector<std::string> names = grid.names();
  const index_t n_cells = grid.fractions.n_cells();
  Json report = report_start(app, args, common, options, names);
  io::MeshData out;
  AdaptFigures figures;
  std::vector<CellFailure> worst;
  std::vector<std::int64_t> bad_input;
  bool stopped = false;
  std::visit(
      [&](const auto& r) {
        for (CellId c : r.bad_input_cells) bad_input.push_back(c.value());
        worst = r.failures;
        stopped = r.stopped_bad_input;
        for (const auto& s : r.steps) times.emplace_back(s.name, s.seconds);
        report["result"] = Json::parse(adapt_result_json(r, n_cells, options.threshold));
        figures = adapt_figures(r, n_cells);
        log_steps(r, options.near_interface);
        if (!stopped) out = adapt_mesh_data(r, names);
      },
      adapt(std::move(grid), options, args.model.empty() ? nullptr : &model.model));
  clock.restart();
  if (stopped) return refuse_bad_input(common, report, times, bad_input, worst, options.threshold);
  record_provenance(app, input, out);
  io::write_mesh(out, common.output, common.write_options());
  times.emplace_back("write", clock.seconds());
  return finish(common, report, times, options, figures, worst);
}

// On the ranks of an MPI job (adapt_on_ranks.h): each rank reads its part of the input (a
// structured grid's slab, or the cells PT-Scotch gives it of an unstructured mesh) with the
// ghost layers around it, adapts it with the others, and writes its part as one piece.
int run_adapt_on_ranks(const CLI::App& app, Args& args, cli::CommonOptions& common,
                       const dist::Communicator& comm) {
  AdaptOptions options;
  dist::on_every_rank(comm, [&] {
    cli::check_files({{"input", args.input}, {"--model", args.model}},
                     {{"-o", common.output, true, true}, {"--json", common.json}});
    cli::check_rank_output("-o", common.output, args.gather, false);
    options = adapt_options(args, common);
    if (options.correction.enabled)
      throw OptionError(
          "--correction: the target correction on the whole grid's model runs on one process");
  });
  if (comm.rank() > 0) options.progress = nullptr;
  Timer clock;
  PhaseTimes times;
  io::RankInput in = io::read_mesh_on_ranks(comm, args.input, args.in.read_options(),
                                              adapt_ghost_layers);
  if (!args.in.fractions.labels.empty())
    args.in.fractions.label_values = cli::grid_labels(comm, args.in, args.input, in);
  AssignedGrid grid;
  io::MeshData input;
  dist::on_every_rank(comm, [&] {
    // A rank adapts the cells it read: its own and the ghost layers around them.
    const index_t cells = in.data.n_cells();
    cli::check_memory(
        "adapting " + std::to_string(cells) + " cells on rank " + std::to_string(comm.rank()),
        static_cast<double>(cells) * cli::adapt_bytes_per_cell, common.memory_limit());
    grid = io::to_assigned_grid(in.data, args.in.grid(io::MaterialSource::array), args.input);
    input = metadata_only(in.data);
    // Without --correction nothing uses the model: it is only checked against the grid.
    if (!args.model.empty() && comm.rank() == 0) (void)read_model(args.model, grid.names());
  });
  if (!args.model.empty())
    log_info("--model: checked against the grid; without --correction adapt does not use it");
  const std::vector<std::string> names = grid.names();
  times.emplace_back("read", clock.seconds());
  std::optional<SlabPlace> slab;
  if (in.structured)
    slab = SlabPlace{in.slab, in.shape.cells[static_cast<std::size_t>(in.shape.dim - 1)]};
  RankAdaptResult r = adapt(std::move(grid), options, {comm, in.slab.block}, slab);
  times.insert(times.end(), r.times.begin(), r.times.end());
  Json report = report_start(app, args, common, options, names);
  report["result"] = Json::parse(adapt_figures_json(r.total));
  report["result"]["failures"] = Json::parse(failures_json(r.failures, options.threshold));
  report["result"]["input_cells_below_threshold"] = r.bad_input_cells.size();
  if (comm.rank() != 0) common.json.clear();  // rank 0 writes the report (and logs)
  if (r.stopped_bad_input) {
    report["ranks"] = cli::ranks_json(comm, in);
    return refuse_bad_input(common, report, times, r.bad_input_cells, r.failures,
                            options.threshold);
  }
  clock.restart();
  io::MeshData piece = std::visit([&](const auto& p) { return adapt_mesh_data(p, names); }, r.part);
  r.part = AnyAdaptResult();
  record_provenance(app, input, piece);
  if (args.gather) io::drop_next_piece_nodes(piece, r.counted_above);
  io::write_disjoint_pieces(comm, piece, common.output, args.gather, common.write_options(),
                             common.memory_limit());
  times.emplace_back("write", clock.seconds());
  report["ranks"] = cli::ranks_json(comm, in);
  report["ranks"].update(Json::parse(rank_adapt_json(r)));
  return finish(common, report, times, options, r.total, r.failures);
}

// The input, the method, the guarantee and the controlled move.
void add_method_options(CLI::App& app, Args& args) {
  app.add_option("input", args.input, "Assigned grid (.vtu, .vtk, ...)")->required();
  app.add_option("--method", args.method,
                 "guaranteed: controlled move and move-smooth loop keeping every cell >= "
                 "--threshold (Fig. 10-b); base: direct "
                 "move, global pillowing, smoothing (Fig. 10-a), no guarantee")
      ->check(CLI::IsMember({"base", "guaranteed"}))
      ->capture_default_str();
  app.add_option("--threshold", args.options.threshold, "Minimum scaled Jacobian S_q")
      ->check(CLI::Range(-1.0, 1.0))
      ->capture_default_str();
  app.add_option("--min-edge", args.options.min_edge,
                 "Shortest edge every cell keeps, relative to its local input size (the mean "
                 "edge length of the input cell it comes from); 0: no size criterion")
      ->check(CLI::Range(0.0, 0.999999))
      ->capture_default_str();
  app.add_option("--steps", args.options.move.steps, "Steps of the controlled move")
      ->check(cli::positive)
      ->capture_default_str();
  app.add_flag("--drag,!--no-drag", args.options.move.drag,
               "guaranteed: retry a refused step of the controlled move with the free nodes "
               "ahead of the node moved along, then with all its free neighbours (default on)");
  app.add_option("--smooth-iterations", args.options.smooth.iterations, "Smoothing sweeps")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_flag("--allow-bad-input", args.options.allow_bad_input,
               "guaranteed: run even when input cells are below --threshold (exit 3 otherwise)");
}

// The rounds of the guaranteed method and the layers it gives nodes to move into.
void add_layer_options(CLI::App& app, Args& args) {
  app.add_option("--max-loops", args.options.max_loops, "guaranteed: move-smooth rounds at most")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--reach-passes", args.options.reach.passes,
                 "guaranteed: passes putting the nodes still off their surface after the loop "
                 "on it, and at the end the nodes short of their targets on them, their "
                 "neighbours repairing the cells (0: none)")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--cavity-range", args.options.cavity.range,
                 "guaranteed: vertex distance of the cavities pillowed around blocked nodes "
                 "(0: no cavity pillowing)")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--layers", args.layers,
                 "guaranteed: where nodes get new cells to move into: cavities (around the nodes "
                 "the first move left short, paper sec. 5.2), first (each material's interfaces "
                 "pillowed before the move), both; automatic: cavities in 2D; in 3D first, and "
                 "when fewer than --enough-share of the interface nodes end near their "
                 "interface, cavities too, keeping the result with more of them")
      ->check(CLI::IsMember({"automatic", "cavities", "first", "both"}))
      ->capture_default_str();
  app.add_option("--late-cavity-share", args.options.late_cavity_share,
                 "guaranteed: at the end, cavities around the nodes still short of their targets "
                 "when they are at most this share of the interface nodes, kept when a few more "
                 "move-smooth rounds then bring them closer (0: none)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--enough-share", args.options.enough_share,
                 "guaranteed, --layers automatic, 3D: the share of interface nodes near their "
                 "interface with a first layer beyond which cavities are not tried")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--interface-pillow-rounds", args.options.interface_pillow.rounds,
                 "guaranteed: attempts at pillowing each material's interfaces before the first "
                 "move, kept only where every cell meets the criteria, when the runs of "
                 "--mend-rounds did not end with every cell passing (0: no such pillowing)")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--interface-pillow-carve", args.options.interface_pillow.carve,
                 "guaranteed: vertex distance of the cells left out of a material's layer "
                 "around a cell that fails the criteria, before the next attempt")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_flag("--sheet-layers,!--no-sheet-layers", args.options.interface_pillow.sheet_layers,
               "guaranteed: also pillow the cells one cell thick between two other materials, "
               "which are otherwise left out of their material's layer (default off)");
  app.add_option("--mend-rounds", args.options.mend_rounds,
                 "guaranteed, first layer: runs that keep each material's layer with its failing "
                 "cells for the moves to mend, leaving it out around what stayed failing; then "
                 "the layer is carved where it fails before the move (0: only that)")
      ->check(cli::non_negative)
      ->capture_default_str();
}

// Where the interface nodes go: their targets and the volume offset.
void add_target_options(CLI::App& app, Args& args) {
  app.add_option("--near-interface", args.options.near_interface,
                 "guaranteed: a node within this many local sizes of its interface surface has "
                 "reached it; farther ones are reported as blocked")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--volume-offset", args.options.targets.volume_offset,
                 "Offset each material's interface targets along their normal until the grid "
                 "with its nodes on them holds the material's input volume: on, off, or "
                 "automatic (3D only)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, VolumeOffset>{{"automatic", VolumeOffset::automatic},
                                              {"on", VolumeOffset::on},
                                              {"off", VolumeOffset::off}},
          CLI::ignore_case))
      ->option_text("TEXT:{automatic,on,off}=automatic");
  app.add_option("--volume-sweeps", args.options.targets.volume_sweeps,
                 "Volume offset: sweeps at most")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--volume-max-shift", args.options.targets.volume_max_shift,
                 "Farthest a target moves for the volume, in local sizes")
      ->check(cli::non_negative)
      ->capture_default_str();
}

// The geometric model and the target correction on it (paper sec. 5.3).
void add_correction_options(CLI::App& app, Args& args) {
  app.add_option("--model", args.model,
                 "guaranteed, 3D: the geometric model of hexadapt-reconstruct --model (its .vtk), "
                 "on which --correction smooths the targets first (paper sec. 5.3)");
  app.add_flag("--correction,!--no-correction", args.options.correction.enabled,
               "guaranteed, 3D, with --model: correct the targets on the model (paper sec. "
               "5.3; off by default: it costs reach and volume once interfaces are pillowed "
               "first)");
  app.add_option("--correction-iterations", args.options.correction.iterations,
                 "Target correction: smoothing sweeps")
      ->check(cli::non_negative)
      ->capture_default_str();
  app.add_option("--correction-relaxation", args.options.correction.relaxation,
                 "Target correction: share of the way to the smoothed position per sweep")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--correction-radius", args.options.correction.search_radius,
                 "Target correction: model search radius, in mean interface edge lengths")
      ->check(cli::positive)
      ->capture_default_str();
  app.add_option("--correction-max-shift", args.options.correction.max_shift,
                 "Target correction: farthest a target moves by smoothing, in mean edge lengths")
      ->check(cli::positive)
      ->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Adapts an assigned grid (material + vf_* cell arrays, from hexadapt-assign) into a\n"
      "conformal mesh whose cells each hold one material, with point arrays 'target',\n"
      "'distance', 'surface_distance', 'blocked' (1: the node ended farther than\n"
      "--near-interface local sizes from its interface surface, the cells around it refusing\n"
      "the move; 2: and no cavity around it could be pillowed), and the cell array\n"
      "'local_size'. Exit code 3 when output cells end below --threshold or with an edge\n"
      "shorter than --min-edge x local_size, or when input cells do (guaranteed method,\n"
      "nothing written).",
      "hexadapt-adapt"};
  Args args;
  cli::CommonOptions common;
  add_method_options(app, args);
  add_layer_options(app, args);
  add_target_options(app, args);
  add_correction_options(app, args);
  cli::add_input_options(app, args.in);
  cli::add_common_options(app, common);
  cli::add_write_options(app, common);
  app.add_flag("--gather", args.gather,
               "Under mpirun on several ranks: write one file of the whole mesh (any format) "
               "instead of a .vtu piece per rank and the .pvtu naming them");
  return cli::run_on_ranks(app, argc, argv, common, [&](const dist::Communicator& comm) {
    return comm.size() > 1 ? run_adapt_on_ranks(app, args, common, comm)
                           : run_adapt(app, args, common);
  });
}
