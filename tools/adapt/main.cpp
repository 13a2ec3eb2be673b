// hexadapt-adapt: moves the interface nodes of an assigned grid onto the material interfaces
// and pillows, giving a conformal mesh whose cells each hold one material (paper sec. 5).
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "cli.h"
#include "hexadapt/adapt/adapt.h"
#include "hexadapt/adapt/adapt_io.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/reconstruct/model_io.h"
#include "input_record.h"

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
};

// The cells failing a criterion: which one, where, and by how much.
Json failures_json(const std::vector<CellFailure>& failures, double threshold) {
  Json out = Json::array();
  for (const CellFailure& f : failures) {
    Json criteria = Json::array();
    if (f.shape_failed(threshold)) criteria.push_back("threshold");
    if (f.size_failed()) criteria.push_back("min_edge");
    out.push_back({{"cell", f.cell.value()},
                   {"failed", criteria},
                   {"scaled_jacobian", f.scaled_jacobian},
                   {"shortest_edge", f.shortest_edge},
                   {"min_edge_length", f.min_length},
                   {"centroid", {f.centroid.x(), f.centroid.y(), f.centroid.z()}}});
  }
  return out;
}

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

template <class M>
Json result_json(const AdaptResult<M>& r, index_t input_cells, double threshold) {
  Json j;
  j["cells_in"] = input_cells;
  j["cells"] = r.mesh.n_cells();
  j["nodes"] = r.mesh.n_nodes();
  j["interface_nodes"] = r.n_interface_nodes;
  j["reached"] = r.n_reached;
  j["near_interface"] = r.n_near_interface;
  j["dist_init"] = r.dist_init;
  j["dist_final"] = r.dist_final;
  j["surface_dist_init"] = r.surface_dist_init;
  j["surface_dist_final"] = r.surface_dist_final;
  j["surface_dist_ratio"] =
      r.surface_dist_init > 0 ? r.surface_dist_final / r.surface_dist_init : 0.0;
  j["min_quality"] = r.min_quality;
  j["cells_below_threshold"] = r.n_below_threshold;
  j["cells_inverted"] = r.n_inverted;
  j["cells_below_min_edge"] = r.n_below_min_edge;
  j["min_edge_ratio"] = r.min_edge_ratio;
  j["failures"] = failures_json(r.failures, threshold);
  j["dist_ratio"] = r.dist_init > 0 ? r.dist_final / r.dist_init : 0.0;
  j["input_min_quality"] = r.input_min_quality;
  j["input_cells_below_threshold"] = r.bad_input_cells.size();
  j["move_smooth_loops"] = r.loops;
  j["blocked_nodes"] = r.n_blocked;
  if (r.farthest.valid()) {
    const Vec3 p = r.mesh.point(r.farthest);
    j["farthest_node"] = {{"node", r.farthest.value()},
                          {"surface_distance", r.farthest_distance},
                          {"local_size", r.farthest_local_size},
                          {"position", {p.x(), p.y(), p.z()}}};
  }
  Json pillows = Json::array();
  for (const auto& a : r.interface_pillows)
    pillows.push_back({{"material", a.material},
                       {"rounds", a.rounds},
                       {"kept", a.kept},
                       {"left_out", a.left_out},
                       {"sheet_cells", a.sheet_cells},
                       {"layer_cells", a.layer_cells},
                       {"failing", a.failing}});
  j["interface_pillows"] = pillows;
  j["mend_failing"] = r.mend_failing;
  j["reach"] = {{"off_surface", r.reach.off_surface},
                {"still_off", r.reach.still_off},
                {"moves", r.reach.moves},
                {"passes", r.reach.passes}};
  j["layers"] = to_string(r.layers);
  j["other_near_interface"] = r.other_near_interface;
  j["interface_layer_cells"] = r.n_interface_layer_cells;
  j["cavities_tried"] = r.cavities.size();
  j["cavities_published"] = r.n_cavities_published;
  j["cells_added_by_pillowing"] = r.n_cells_added;
  Json cavities = Json::array();
  for (const auto& a : r.cavities) {
    Json seeds = Json::array();
    for (NodeId s : a.seeds) seeds.push_back(s.value());
    cavities.push_back({{"material", a.material},
                        {"seeds", seeds},
                        {"range", a.range},
                        {"cells", a.cells},
                        {"published", a.published},
                        {"min_quality", a.min_quality}});
  }
  j["cavities"] = cavities;
  Json blocking = Json::array();
  for (const auto& [c, q] : r.blocking_cells)
    blocking.push_back({{"cell", c.value()}, {"quality", q}});
  j["blocking_cells"] = blocking;
  Json steps = Json::array();
  for (const auto& s : r.steps)
    steps.push_back({{"name", s.name},
                     {"min_quality", s.min_quality},
                     {"cells", s.cells},
                     {"seconds", s.seconds}});
  j["steps"] = steps;
  const TargetCorrectionResult& c = r.correction;
  Json correction = {{"ran", c.ran}};
  if (c.ran) {
    const auto it = std::find_if(r.steps.begin(), r.steps.end(),
                                 [](const AdaptStep& s) { return s.name == "correct"; });
    correction["seconds"] = it != r.steps.end() ? it->seconds : 0.0;
    correction["surface_quads"] = c.n_faces;
    correction["surface_nodes"] = c.n_surface_nodes;
    correction["curve_nodes"] = c.n_curve_nodes;
    correction["fixed_nodes"] = c.n_fixed_nodes;
    correction["unprojected_nodes"] = c.n_unprojected;
    correction["off_model_nodes"] = c.n_off_model;
    correction["min_quad_quality_before"] = c.min_quality_before;
    correction["min_quad_quality_projected"] = c.min_quality_projected;
    correction["min_quad_quality_after"] = c.min_quality_after;
    correction["quads_below_0.3_before"] = c.n_poor_before;
    correction["quads_below_0.3_after"] = c.n_poor_after;
    correction["mean_target_displacement"] = c.mean_displacement;
    correction["max_target_displacement"] = c.max_displacement;
    correction["sweeps"] = c.sweeps;
  } else {
    correction["skipped"] = c.skipped;
  }
  j["correction"] = correction;
  const TargetSpacingResult& sp = r.spacing;
  j["target_spacing"] = {{"short_edges", sp.short_edges}, {"moved_targets", sp.moved},
                         {"left_short", sp.left_short},   {"max_shift", sp.max_shift},
                         {"sweeps", sp.sweeps},           {"swapped", sp.swapped}};
  const LateCavities& late = r.late_cavities;
  j["late_cavities"] = {{"short_nodes", late.short_nodes},
                        {"tried", late.tried},
                        {"published", late.published},
                        {"kept", late.kept}};
  j["late_reach"] = {{"short_nodes", r.late_reach.off_surface},
                     {"still_short", r.late_reach.still_off},
                     {"moves", r.late_reach.moves},
                     {"passes", r.late_reach.passes}};
  return j;
}

// The reconstruction's model (hexadapt-reconstruct --model), its materials checked against
// the grid's.
reconstruct::ModelFile read_model(const std::string& path, const Fractions& fractions) {
  reconstruct::ModelFile m = reconstruct::read_model_vtk(path);
  if (m.materials != fractions.names()) {
    std::string want, got;
    for (const auto& n : fractions.names()) want += " " + n;
    for (const auto& n : m.materials) got += " " + n;
    throw InputError(path, "title line",
                     "the model's materials (" + got + " ) are not the grid's (" + want + " )");
  }
  return m;
}

// Nodes that stay away from their interface are said even when the run succeeds: how many,
// their share, and the farthest.
template <class M>
void warn_blocked(const AdaptResult<M>& r, double near) {
  if (r.n_blocked == 0 || !r.farthest.valid()) return;
  const Vec3 p = r.mesh.point(r.farthest);
  char text[512];
  std::snprintf(text, sizeof text,
                "%d of %d interface nodes (%.1f%%) stay farther than %g local sizes from their "
                "interface; the farthest, node %d at (%.6g, %.6g, %.6g), by %.4g (%.3g local "
                "sizes): see the 'blocked' and 'surface_distance' point arrays",
                r.n_blocked, r.n_interface_nodes, 100.0 * r.n_blocked / r.n_interface_nodes, near,
                r.farthest.value(), p.x(), p.y(), p.z(), r.farthest_distance,
                r.farthest_local_size > 0 ? r.farthest_distance / r.farthest_local_size : 0.0);
  log_warning(text);
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
int refuse_bad_input(const cli::CommonOptions& common, Json& report, const PhaseTimes& times,
                     const std::vector<CellId>& bad, const std::vector<CellFailure>& worst,
                     double threshold) {
  log_warning(std::to_string(bad.size()) + " input cells fail the threshold " +
              std::to_string(threshold) +
              " or the size criterion (--min-edge); the worst:" + failures_text(worst, threshold) +
              "\nnothing written (--allow-bad-input runs anyway, without the guarantee; "
              "--min-edge 0 drops the size criterion)");
  Json cells = Json::array();
  for (CellId c : bad) cells.push_back(c.value());
  report["bad_input_cells"] = cells;
  report["threshold_met"] = false;
  report["exit_code"] = cli::target_missed;
  report["times"] = cli::phase_times_json(times);
  cli::write_report(common, report);
  return cli::target_missed;
}

int run_adapt(const CLI::App& app, const Args& args, const cli::CommonOptions& common) {
  cli::check_files({{"input", args.input}, {"--model", args.model}},
                   {{"-o", common.output, true, true}, {"--json", common.json}});
  AdaptOptions options = args.options;
  options.method = parse_adapt_method(args.method);
  options.layers = parse_layer_strategy(args.layers);
  options.progress = cli::terminal_progress(common);

  Timer clock;
  PhaseTimes times;
  io::MeshData in = io::read_mesh(args.input, args.in.read_options());
  cli::check_memory("adapting " + std::to_string(in.n_cells()) + " cells",
                    static_cast<double>(in.n_cells()) * cli::adapt_bytes_per_cell,
                    common.memory_limit());
  const AssignedGrid grid =
      io::to_assigned_grid(in, args.in.grid(io::MaterialSource::array), args.input);
  reconstruct::ModelFile model;
  if (!args.model.empty()) model = read_model(args.model, grid.fractions);
  times.emplace_back("read", clock.seconds());
  clock.restart();

  Json report = cli::report_header(app);
  report["input"] = args.input;
  report["output"] = common.output;
  report["method"] = to_string(options.method);
  report["threshold"] = options.threshold;
  report["min_edge"] = options.min_edge;
  report["layers"] = to_string(options.layers);
  report["steps"] = options.move.steps;
  report["drag"] = options.move.drag;
  report["materials"] = grid.names();
  report["model"] = args.model;
  io::MeshData out;
  index_t below = 0;
  std::vector<CellId> bad_input;
  std::vector<CellFailure> worst;
  bool stopped = false;
  std::visit(
      [&](const auto& r) {
        bad_input = r.bad_input_cells;
        worst = r.failures;
        stopped = r.stopped_bad_input;
        for (const auto& s : r.steps) times.emplace_back(s.name, s.seconds);
        report["result"] = result_json(r, grid.fractions.n_cells(), options.threshold);
        below = r.n_below_threshold + r.n_below_min_edge;
        log_steps(r, options.near_interface);
        if (!r.stopped_bad_input) warn_blocked(r, options.near_interface);
        out = adapt_mesh_data(r, grid.names());
      },
      adapt(grid, options, args.model.empty() ? nullptr : &model.model));
  clock.restart();
  if (stopped) return refuse_bad_input(common, report, times, bad_input, worst, options.threshold);
  for (auto& kv : cli::provenance(app)) out.metadata.push_back(kv);
  cli::pass_input_record(in, out);
  io::write_mesh(out, common.output, common.write_options());
  times.emplace_back("write", clock.seconds());
  report["threshold_met"] = below == 0;
  report["exit_code"] = below == 0 ? cli::ok : cli::target_missed;
  report["times"] = cli::phase_times_json(times);
  cli::write_report(common, report);
  if (below > 0) {
    log_warning(std::to_string(below) + " output cells fail the threshold " +
                std::to_string(options.threshold) + " or the size criterion (the " + args.method +
                " method gives no guarantee); the worst:" +
                failures_text(worst, options.threshold) + "\nmesh written to " + common.output);
    return cli::target_missed;
  }
  return cli::ok;
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
  return cli::run(app, argc, argv, common, [&] { return run_adapt(app, args, common); });
}
