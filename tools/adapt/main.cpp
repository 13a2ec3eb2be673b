// hexadapt-adapt: moves the interface nodes of an assigned grid onto the material interfaces
// and pillows, giving a conformal mesh whose cells each hold one material (paper sec. 5).
#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "cli.h"
#include "cut_bands.h"
#include "hexadapt/adapt/adapt.h"
#include "hexadapt/adapt/adapt_io.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/routing.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/unit_frame.h"
#include "hexadapt/reconstruct/model_io.h"
#include "input_record.h"
#include "memory.h"
#include "own_part.h"
#include "rank_files.h"
#include "ranks.h"
#include "shared_nodes.h"

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
// `bad`: their ids, increasing; `worst`: failures_text of the worst.
int refuse_bad_input(const cli::CommonOptions& common, Json& report, const PhaseTimes& times,
                     const std::vector<std::int64_t>& bad, const std::string& worst,
                     double threshold) {
  log_warning(std::to_string(bad.size()) + " input cells fail the threshold " +
              std::to_string(threshold) +
              " or the size criterion (--min-edge); the worst:" + worst +
              "\nnothing written (--allow-bad-input runs anyway, without the guarantee; "
              "--min-edge 0 drops the size criterion)");
  report["bad_input_cells"] = bad;
  report["threshold_met"] = false;
  report["exit_code"] = cli::target_missed;
  report["times"] = cli::phase_times_json(times);
  cli::write_report(common, report);
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

// The metadata of `data` (its record of how it was read); its cells and arrays released.
io::MeshData metadata_only(io::MeshData& data) {
  io::MeshData out;
  out.metadata = std::move(data.metadata);
  data = io::MeshData();
  return out;
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
  AssignedGrid grid =
      io::to_assigned_grid(in, args.in.grid(io::MaterialSource::array), args.input);
  const io::MeshData input = metadata_only(in);
  reconstruct::ModelFile model;
  if (!args.model.empty()) model = read_model(args.model, grid.fractions);
  times.emplace_back("read", clock.seconds());
  clock.restart();

  const std::vector<std::string> names = grid.names();
  const index_t n_cells = grid.fractions.n_cells();
  Json report = report_start(app, args, common, options, names);
  io::MeshData out;
  index_t below = 0;
  std::vector<std::int64_t> bad_input;
  std::vector<CellFailure> worst;
  bool stopped = false;
  std::visit(
      [&](const auto& r) {
        for (CellId c : r.bad_input_cells) bad_input.push_back(c.value());
        worst = r.failures;
        stopped = r.stopped_bad_input;
        for (const auto& s : r.steps) times.emplace_back(s.name, s.seconds);
        report["result"] = result_json(r, n_cells, options.threshold);
        below = r.n_below_threshold + r.n_below_min_edge;
        log_steps(r, options.near_interface);
        if (!r.stopped_bad_input) warn_blocked(r, options.near_interface);
        out = adapt_mesh_data(r, names);
      },
      adapt(std::move(grid), options, args.model.empty() ? nullptr : &model.model));
  clock.restart();
  if (stopped)
    return refuse_bad_input(common, report, times, bad_input,
                            failures_text(worst, options.threshold), options.threshold);
  for (auto& kv : cli::provenance(app)) out.metadata.push_back(kv);
  cli::pass_input_record(input, out);
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

// The rings of cells on each side of a cut whose nodes the second pass moves on.
constexpr int cut_rings = 4;

// The layers of cells a rank reads and adapts beyond its own on each side: a node's target
// comes from the faces around it, their cells' fraction gradients (fitted over the cells
// around those) and the columns of three cells across a sheet; three layers hold all of them
// for the nodes of the own layers, the cuts' too, and the cells whose layers cross a cut.
constexpr int target_ghost_layers = 3;

// A rank's part of the input: the cells it read and adapts (its own and the ghost layers
// around them), which of them are its own, and the targets of their nodes.
struct HeldPart {
  AssignedGrid read;               ///< the cells read
  std::vector<std::string> names;  ///< the materials'
  io::MeshData input;              ///< the input's metadata only (its record of how it was read)
  index_t first_cell = 0, own_cells = 0;  ///< the own cells among those read: [first, first + own)
  /// The input nodes a part lists first, in order (a slab's own node layers; none of a mesh).
  std::array<index_t, 2> first_nodes{};
  /// What the volume offset's sums count here: the own cells, and the nodes this rank decides
  /// for (each node of the whole input counted by one rank).
  IdVector<CellId, char> counted_cells;
  IdVector<NodeId, char> counted_nodes;
  /// The cuts' nodes: those of the own cells that other ranks' own cells use too, frozen so
  /// that the parts fit together there.
  IdVector<NodeId, char> frozen;
  std::vector<int> cell_owner;  ///< the rank owning each cell read (cell_owners)
  /// Of the nodes read; those of the own cells as one process computes them on the whole input.
  Targets targets;
};

// The assigned grid of the cells `in` holds, its names and its metadata; `in`'s data released.
HeldPart held_part(cli::RankInput& in, const Args& args) {
  HeldPart s;
  s.read = io::to_assigned_grid(in.data, args.in.grid(io::MaterialSource::array), args.input);
  s.names = s.read.names();
  s.input = metadata_only(in.data);
  return s;
}

// The part of a structured grid's slab: its own layers and the ghost layers around them.
HeldPart slab_part(cli::RankInput& in, const Args& args) {
  const auto axis = static_cast<std::size_t>(in.shape.dim - 1);
  const int first = in.slab.first_layer;
  const std::array<int, 2> owned{in.slab.owned_layers[0] - first, in.slab.owned_layers[1] - first};
  const bool below = in.slab.owned_layers[0] > 0;
  const bool above = in.slab.owned_layers[1] < in.shape.cells[axis];
  const index_t n_cells = in.data.n_cells();
  const auto n_nodes = static_cast<index_t>(in.data.points.size());
  HeldPart s = held_part(in, args);
  const int held = in.slab.held[axis];
  const index_t cells = n_cells / held, plane = n_nodes / (held + 1);
  s.first_cell = in.slab.block.owned_cell_first;
  s.own_cells = in.slab.block.owned_cell_end - s.first_cell;
  s.first_nodes = {owned[0] * plane, (owned[1] + 1) * plane};
  s.counted_cells.assign(static_cast<std::size_t>(n_cells), 0);
  for (index_t c = owned[0] * cells; c < owned[1] * cells; ++c) s.counted_cells[CellId(c)] = 1;
  // A cut's nodes are counted by the rank above it.
  s.counted_nodes.assign(static_cast<std::size_t>(n_nodes), 0);
  const int last = above ? owned[1] - 1 : owned[1];
  for (index_t v = owned[0] * plane; v < (last + 1) * plane; ++v) s.counted_nodes[NodeId(v)] = 1;
  s.frozen.assign(static_cast<std::size_t>(n_nodes), 0);
  for (index_t k = 0; k < plane; ++k) {
    if (below) s.frozen[NodeId(owned[0] * plane + k)] = 1;
    if (above) s.frozen[NodeId(owned[1] * plane + k)] = 1;
  }
  return s;
}

// The part of an unstructured mesh cut by PT-Scotch: its own cells (the first ones) and the
// ghost layers around them.
HeldPart mesh_part(cli::RankInput& in, const Args& args) {
  const dist::Block& block = in.slab.block;
  HeldPart s = held_part(in, args);
  s.own_cells = block.owned_cell_end;
  std::visit(
      [&](const auto& mesh) {
        s.counted_cells.assign(static_cast<std::size_t>(mesh.n_cells()), 0);
        s.counted_nodes.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
        s.frozen.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
        IdVector<NodeId, char> in_own(static_cast<std::size_t>(mesh.n_nodes()), 0);
        for (CellId c : id_range<CellId>(mesh.n_cells())) {
          const bool own = block.owns(c);
          s.counted_cells[c] = own;
          for (NodeId v : mesh.cell_nodes(c))
            if (own)
              in_own[v] = 1;
            else
              s.frozen[v] = 1;  // a ghost's node; the cuts' are the own cells' among them
        }
        for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
          s.frozen[v] = s.frozen[v] && in_own[v];
          s.counted_nodes[v] = block.owns(v);
        }
      },
      s.read.mesh);
  return s;
}

// The rank owning each cell `in` holds: of a slab, the last rank whose own layers start at
// the cell's layer or before; of a mesh, itself or, for a ghost, the rank listing it among its
// own cells. Every rank calls it.
std::vector<int> cell_owners(const dist::Communicator& comm, const cli::RankInput& in) {
  const dist::Block& block = in.slab.block;
  std::vector<int> owner;
  if (in.structured) {
    const std::vector<std::int64_t> starts =
        dist::all_gather_values(comm, std::vector<std::int64_t>{in.slab.owned_layers[0]});
    const auto axis = static_cast<std::size_t>(in.shape.dim - 1);
    const index_t per_layer = block.held_cells / in.slab.held[axis];
    for (index_t c = 0; c < block.held_cells; ++c) {
      const std::int64_t layer = in.slab.first_layer + c / per_layer;
      owner.push_back(
          static_cast<int>(std::upper_bound(starts.begin(), starts.end(), layer) - starts.begin()) -
          1);
    }
    return owner;
  }
  const auto first_ghost = static_cast<std::ptrdiff_t>(block.owned_cell_end);
  const std::vector<std::int64_t> own(block.cell_ids.begin(), block.cell_ids.begin() + first_ghost),
      ghosts(block.cell_ids.begin() + first_ghost, block.cell_ids.end());
  owner.assign(own.size(), comm.rank());
  for (const std::vector<int>& o : dist::other_holders(comm, ghosts, own)) {
    if (o.size() != 1)
      throw InternalError("a ghost cell owned by " + std::to_string(o.size()) + " ranks");
    owner.push_back(o.front());
  }
  return owner;
}

// Replaces each value with its sum over the ranks, added in rank order. Every rank calls it.
std::function<void(std::vector<double>&)> summed_over_ranks(const dist::Communicator& comm) {
  return [&comm](std::vector<double>& values) {
    const std::vector<double> all = dist::all_gather_values(comm, values);
    std::fill(values.begin(), values.end(), 0.0);
    for (std::size_t k = 0; k < all.size(); ++k) values[k % values.size()] += all[k];
  };
}

// Sends to[k] (global ids of cells) to peers[k]; what the peers send, in this rank's ids.
std::vector<CellId> received_cells(const dist::Communicator& comm, const std::vector<int>& peers,
                                   std::vector<std::vector<std::int64_t>> to,
                                   const dist::Block& block) {
  std::vector<dist::Buffer> out(peers.size());
  for (std::size_t k = 0; k < peers.size(); ++k) out[k].put_vector(to[k]);
  std::vector<CellId> cells;
  for (dist::Buffer& b : dist::exchange(comm, peers, std::move(out)))
    for (std::int64_t g : b.get_vector<std::int64_t>()) cells.push_back(block.local_cell(g));
  return cells;
}

// The guaranteed method's decisions taken by every rank together (RankDecisions): a cell that
// the mending run of any rank holding it left failing is left out by all of them (each rank
// sends its failing ghosts to their owners, which send back every holder's verdicts on their
// own cells); the shares of the automatic choice are summed. Every rank calls it.
RankDecisions rank_decisions(const dist::Communicator& comm, const HeldPart& s,
                             const dist::Block& block) {
  // Shared by the copies of the options the pipeline makes: the rank's own cells (global
  // ids, increasing), the other ranks holding each, and every rank it exchanges cells with.
  struct Holders {
    std::vector<std::int64_t> own;
    std::vector<std::vector<int>> of_own;
    std::vector<int> peers;
    std::size_t slot(int q) const {
      return static_cast<std::size_t>(std::lower_bound(peers.begin(), peers.end(), q) -
                                      peers.begin());
    }
  };
  const auto held = std::make_shared<Holders>();
  std::vector<std::int64_t> ghosts;
  for (CellId c : id_range<CellId>(static_cast<index_t>(s.cell_owner.size())))
    (s.cell_owner[c.idx()] == comm.rank() ? held->own : ghosts).push_back(block.global(c));
  std::sort(ghosts.begin(), ghosts.end());  // a slab's are in order already, a list's too
  held->of_own = dist::other_holders(comm, held->own, ghosts);
  for (const std::vector<int>& q : held->of_own)
    held->peers.insert(held->peers.end(), q.begin(), q.end());
  for (int q : s.cell_owner)
    if (q != comm.rank()) held->peers.push_back(q);
  std::sort(held->peers.begin(), held->peers.end());
  held->peers.erase(std::unique(held->peers.begin(), held->peers.end()), held->peers.end());
  RankDecisions d;
  d.left_out = [&comm, &s, &block, held](std::vector<CellId>& cells) {
    const Holders& h = *held;
    const bool mine = !cells.empty();
    std::vector<std::vector<std::int64_t>> to(h.peers.size());
    for (CellId c : cells)
      if (s.cell_owner[c.idx()] != comm.rank())
        to[h.slot(s.cell_owner[c.idx()])].push_back(block.global(c));
    std::vector<CellId> failing = received_cells(comm, h.peers, std::move(to), block);
    for (CellId c : cells)
      if (s.cell_owner[c.idx()] == comm.rank()) failing.push_back(c);
    std::sort(failing.begin(), failing.end());
    failing.erase(std::unique(failing.begin(), failing.end()), failing.end());
    to.assign(h.peers.size(), {});
    for (CellId c : failing) {
      const std::int64_t g = block.global(c);
      const auto at = std::lower_bound(h.own.begin(), h.own.end(), g) - h.own.begin();
      for (int q : h.of_own[static_cast<std::size_t>(at)]) to[h.slot(q)].push_back(g);
    }
    for (std::vector<std::int64_t>& ids : to) std::sort(ids.begin(), ids.end());
    std::vector<CellId> back = received_cells(comm, h.peers, std::move(to), block);
    cells.insert(cells.end(), failing.begin(), failing.end());
    cells.insert(cells.end(), back.begin(), back.end());
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return !cli::all_true(comm, !mine);  // some rank's run left a cell failing
  };
  d.add_up = summed_over_ranks(comm);
  return d;
}

// The frame one process adapts the whole grid in (mesh/unit_frame.h): that of every rank's
// layers read together.
template <class M>
UnitFrame whole_frame(const dist::Communicator& comm, const M& mesh) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    low = low.cwiseMin(mesh.point(v));
    high = high.cwiseMax(mesh.point(v));
  }
  const std::vector<double> all = dist::all_gather_values(
      comm, std::vector<double>{low.x(), low.y(), low.z(), high.x(), high.y(), high.z()});
  std::vector<Vec3> corners;
  for (std::size_t k = 0; k + 2 < all.size(); k += 3)
    corners.emplace_back(all[k], all[k + 1], all[k + 2]);
  return unit_frame(corners);
}

// The targets of the nodes read, those of the own cells' nodes as one process computes them on
// the whole input: on the cells read, in the whole input's frame, the volume offset's sums
// over what every rank counts. Every rank calls it.
void part_targets(const dist::Communicator& comm, HeldPart& s, const AdaptOptions& options) {
  std::visit(
      [&](const auto& grid) {
        const UnitFrame frame = whole_frame(comm, grid);
        const auto m = to_local(grid, frame);
        VolumeParts parts;
        parts.counted_cells = s.counted_cells;
        parts.counted_nodes = s.counted_nodes;
        parts.add_up = summed_over_ranks(comm);
        const Targets t = compute_targets(
            m, s.read.fractions, s.read.material,
            boundary_constraints(m, options.boundary.without_frozen()), options.targets, &parts);
        s.targets = t;
        for (Vec3& p : s.targets.position.raw()) p = frame.to_world(p);
        for (InterfaceFace& f : s.targets.faces) f.point = frame.to_world(f.point);
      },
      s.read.mesh);
}

// What a rank's part adds to the run's, one value per figure (counts are exact in a double):
// its cells, and the nodes it counts (a node several ranks' parts hold is the highest one's).
enum Figure {
  cells_in,
  cells,
  nodes,
  interface_nodes,
  reached,
  near,
  blocked,
  frozen_blocked,
  below_threshold,
  inverted,
  below_min_edge,
  dist_init,
  dist_final,
  surface_dist_init,
  surface_dist_final,
  min_quality,
  min_edge_ratio,
  input_min_quality,
  loops,
  seconds,
  n_figures
};

template <class M>
std::vector<double> rank_figures(const AdaptResult<M>& r, const IdVector<NodeId, char>& counted,
                                 index_t input_cells, double time) {
  std::vector<double> f(n_figures, 0.0);
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    if (!counted[v]) continue;
    f[nodes] += 1;
    if (!r.has_target[v]) continue;
    f[interface_nodes] += 1;
    f[reached] += r.distance[v] == 0;
    f[near] += r.near_interface[v] != 0;
    f[blocked] += r.blocked[v] != 0;
    f[frozen_blocked] += r.blocked[v] == static_cast<char>(BlockReason::frozen);
    f[dist_final] += r.distance[v];
    f[surface_dist_final] += r.surface_distance[v];
  }
  f[cells_in] = input_cells;
  f[cells] = r.mesh.n_cells();
  f[below_threshold] = r.n_below_threshold;
  f[inverted] = r.n_inverted;
  f[below_min_edge] = r.n_below_min_edge;
  f[dist_init] = r.dist_init;
  f[surface_dist_init] = r.surface_dist_init;
  f[min_quality] = r.min_quality;
  f[min_edge_ratio] = r.min_edge_ratio;
  f[input_min_quality] = r.input_min_quality;
  f[loops] = r.loops;
  f[seconds] = time;
  return f;
}

// The run's figures from every rank's, in rank order: sums, least qualities, most loops; and
// each rank's own in `per_rank`.
Json combined_result(const std::vector<double>& all, Json& per_rank) {
  std::vector<double> t(n_figures, 0.0);
  for (Figure m : {min_quality, min_edge_ratio, input_min_quality})
    t[m] = std::numeric_limits<double>::infinity();
  per_rank = {{"cells", Json::array()},
              {"nodes", Json::array()},
              {"interface_nodes", Json::array()},
              {"near_interface", Json::array()},
              {"frozen_blocked_nodes", Json::array()},
              {"adapt_seconds", Json::array()}};
  for (std::size_t at = 0; at + n_figures <= all.size(); at += n_figures) {
    const double* f = all.data() + at;
    for (int k = 0; k < n_figures; ++k) {
      if (k == min_quality || k == min_edge_ratio || k == input_min_quality)
        t[k] = std::min(t[k], f[k]);
      else if (k == loops || k == seconds)
        t[k] = std::max(t[k], f[k]);
      else
        t[k] += f[k];
    }
    per_rank["cells"].push_back(static_cast<std::int64_t>(f[cells]));
    per_rank["nodes"].push_back(static_cast<std::int64_t>(f[nodes]));
    per_rank["interface_nodes"].push_back(static_cast<std::int64_t>(f[interface_nodes]));
    per_rank["near_interface"].push_back(static_cast<std::int64_t>(f[near]));
    per_rank["frozen_blocked_nodes"].push_back(static_cast<std::int64_t>(f[frozen_blocked]));
    per_rank["adapt_seconds"].push_back(f[seconds]);
  }
  const auto count = [&](Figure k) { return static_cast<std::int64_t>(t[k]); };
  const auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  return {{"cells_in", count(cells_in)},
          {"cells", count(cells)},
          {"nodes", count(nodes)},
          {"interface_nodes", count(interface_nodes)},
          {"reached", count(reached)},
          {"near_interface", count(near)},
          {"blocked_nodes", count(blocked)},
          {"frozen_blocked_nodes", count(frozen_blocked)},
          {"dist_init", t[dist_init]},
          {"dist_final", t[dist_final]},
          {"dist_ratio", ratio(t[dist_final], t[dist_init])},
          {"surface_dist_init", t[surface_dist_init]},
          {"surface_dist_final", t[surface_dist_final]},
          {"surface_dist_ratio", ratio(t[surface_dist_final], t[surface_dist_init])},
          {"min_quality", t[min_quality]},
          {"cells_below_threshold", count(below_threshold)},
          {"cells_inverted", count(inverted)},
          {"cells_below_min_edge", count(below_min_edge)},
          {"min_edge_ratio", t[min_edge_ratio]},
          {"input_min_quality", t[input_min_quality]},
          {"move_smooth_loops", count(loops)}};
}

// Every rank's `mine`, in rank order.
Json all_ranks(const dist::Communicator& comm, const Json& mine) {
  const std::string text = mine.dump();
  dist::Buffer out;
  out.put_vector(std::vector<char>(text.begin(), text.end()));
  Json all = Json::array();
  for (dist::Buffer& b : dist::all_gather(comm, out)) {
    const std::vector<char> bytes = b.get_vector<char>();
    all.push_back(Json::parse(bytes.begin(), bytes.end()));
  }
  return all;
}

// The worst of every rank's failing cells (ids of the whole run), on every rank: the ten that
// one process would list among them.
std::vector<CellFailure> worst_on_ranks(const dist::Communicator& comm,
                                        const std::vector<CellFailure>& mine) {
  constexpr std::size_t fields = 7;
  std::vector<double> packed;
  for (const CellFailure& f : mine)
    packed.insert(packed.end(),
                  {static_cast<double>(f.cell.value()), f.scaled_jacobian, f.shortest_edge,
                   f.min_length, f.centroid.x(), f.centroid.y(), f.centroid.z()});
  const std::vector<double> all = dist::all_gather_values(comm, packed);
  std::vector<CellFailure> failures;
  for (std::size_t k = 0; k + fields <= all.size(); k += fields) {
    CellFailure f;
    f.cell = CellId(static_cast<index_t>(all[k]));
    f.scaled_jacobian = all[k + 1];
    f.shortest_edge = all[k + 2];
    f.min_length = all[k + 3];
    f.centroid = Vec3(all[k + 4], all[k + 5], all[k + 6]);
    failures.push_back(f);
  }
  return worst_failures(std::move(failures), 10);
}

// The worst failing cells of the output (ids shifted by the cells of the ranks before, as in
// the gathered mesh).
Json rank_failures(const dist::Communicator& comm, const std::vector<CellFailure>& failures,
                   index_t n_cells, double threshold) {
  const std::vector<std::int64_t> counts =
      dist::all_gather_values(comm, std::vector<std::int64_t>{n_cells});
  index_t shift = 0;
  for (int r = 0; r < comm.rank(); ++r)
    shift += static_cast<index_t>(counts[static_cast<std::size_t>(r)]);
  std::vector<CellFailure> mine = failures;
  for (CellFailure& f : mine) f.cell = CellId(f.cell.value() + shift);
  return failures_json(worst_on_ranks(comm, mine), threshold);
}

// A rank's part of the mesh (own_part.h) and the ranks whose parts hold its frozen nodes (a
// cut's nodes and their copies) too.
template <class M>
struct RankMesh {
  cli::OwnPart<M> part;
  cli::SharedNodes shared;
  std::vector<int> across;         ///< per face of part.cut_faces, the rank whose part is across it
  IdVector<NodeId, char> counted;  ///< the nodes this rank counts (SharedNodes::counts)
};
using AnyRankMesh = std::variant<RankMesh<QuadMesh>, RankMesh<HexMesh>>;

// The part of `r` that comes from the rank's own cells, and who else holds its frozen nodes:
// the owners of the input cells around them (a slab's: the rank beside its cut).
template <class M>
RankMesh<M> rank_mesh(const dist::Communicator& comm, AdaptResult<M> r, const HeldPart& s,
                      const dist::Block& block) {
  RankMesh<M> m;
  m.part = cli::own_part(std::move(r), {s.first_cell, s.first_cell + s.own_cells}, s.first_nodes);
  const AdaptResult<M>& own = m.part.result;
  const auto n = static_cast<std::size_t>(own.mesh.n_nodes());
  const int me = comm.rank();
  m.shared.ranks.resize(n);
  m.shared.key.resize(n);
  const auto owner = [&](CellId c) { return s.cell_owner[c.idx()]; };
  for (NodeId v : id_range<NodeId>(own.mesh.n_nodes())) {
    if (v.idx() >= own.sliding.size() || !own.sliding[v].frozen()) continue;
    std::vector<std::int64_t>& key = m.shared.key[v.idx()];
    std::vector<int>& ranks = m.shared.ranks[v.idx()];
    for (CellId c : m.part.around[v.idx()]) {
      key.push_back(block.global(c));
      if (owner(c) != me) ranks.push_back(owner(c));
    }
    std::sort(key.begin(), key.end());
    key.insert(key.begin(), block.global(own.node_origin[v]));
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  }
  for (int q : s.cell_owner)
    if (q != me) m.shared.peers.push_back(q);
  std::sort(m.shared.peers.begin(), m.shared.peers.end());
  m.shared.peers.erase(std::unique(m.shared.peers.begin(), m.shared.peers.end()),
                       m.shared.peers.end());
  for (CellId c : m.part.cut_across) m.across.push_back(owner(c));
  m.counted.assign(n, 0);
  for (NodeId v : id_range<NodeId>(own.mesh.n_nodes())) m.counted[v] = m.shared.counts(v, me);
  return m;
}

// False on every rank when the mending ran out of runs with cells still failing on some rank
// (the last run then carves the layers where they fail, each rank on its own): with the cells
// around the cuts pillowed, the cells beside the frozen cuts can keep failing where one
// process's mending ends (the vortex 64^3 on 3 ranks: 1-2 cells failing after each of 12
// runs, every layer carved away, 94 % of one process's nodes near their interface; 98 % with
// the cuts unpillowed). Every rank calls it.
template <class M>
bool mended(const dist::Communicator& comm, const AdaptResult<M>& r, const AdaptOptions& options) {
  const bool ran_out = options.mend_rounds > 0 &&
                       r.mend_failing.size() == static_cast<std::size_t>(options.mend_rounds) &&
                       r.mend_failing.back() > 0;
  return cli::all_true(comm, !ran_out);
}

// Whether some rank stopped on bad input cells (the guaranteed method does not start from
// them): then `bad` holds every rank's own ones by their ids in the whole grid, as one process
// names them, and `worst` the worst of them. Every rank calls it.
bool stopped_on_input(const dist::Communicator& comm, const AnyAdaptResult& result,
                      const HeldPart& s, const dist::Block& block, std::vector<std::int64_t>& bad,
                      std::vector<CellFailure>& worst) {
  const index_t first = s.first_cell, end = first + s.own_cells;
  const auto own = [&](CellId c) { return c.value() >= first && c.value() < end; };
  bool stopped = false;
  std::vector<std::int64_t> mine;
  std::visit(
      [&](const auto& r) {
        stopped = r.stopped_bad_input;
        for (CellId c : r.bad_input_cells)
          if (own(c)) mine.push_back(block.global(c));
        std::vector<CellFailure> failures;
        for (CellFailure f : r.stopped_bad_input ? r.failures : std::vector<CellFailure>{})
          if (own(f.cell)) {
            f.cell = CellId(static_cast<index_t>(block.global(f.cell)));
            failures.push_back(f);
          }
        worst = worst_on_ranks(comm, failures);
      },
      result);
  bad = dist::all_gather_values(comm, mine);
  const std::vector<char> stops = dist::all_gather_values(comm, std::vector<char>{stopped});
  return std::find(stops.begin(), stops.end(), 1) != stops.end();
}

// On the ranks of an MPI job, after ParMmg's iterative interface displacement: each rank reads
// its part of the input (a structured grid's slab, or the cells PT-Scotch gives it of an
// unstructured mesh) and the ghost layers around it, and adapts them with the nodes it shares
// with other ranks' own cells (the cuts) frozen, the cells around them pillowed as one
// process pillows them (BoundaryOptions::pillow_frozen); its part of the mesh is the cells
// that come from its own cells (own_part.h). The ranks decide the mending together
// (rank_decisions), so the ranks holding a cut lay the same layers across it; where the
// copies of its nodes still do not meet (shared_nodes.h), every rank adapts again with the
// cells around the cuts left unpillowed. Then the nodes around every cut move on, the ranks
// holding them moving the same band (cut_bands.h); each rank writes its part as one piece.
int run_adapt_on_ranks(const CLI::App& app, Args& args, cli::CommonOptions& common,
                       const dist::Communicator& comm) {
  AdaptOptions options = args.options;
  cli::on_every_rank(comm, app, [&] {
    cli::check_files({{"input", args.input}},
                     {{"-o", common.output, true, true}, {"--json", common.json}});
    cli::check_rank_output("-o", common.output, args.gather, false);
    options.method = parse_adapt_method(args.method);
    options.layers = parse_layer_strategy(args.layers);
    if (options.method != AdaptMethod::guaranteed)
      throw OptionError("--method " + args.method +
                        " runs on one process: on several ranks, guaranteed");
    if (!args.model.empty())
      throw OptionError(
          "--model: the target correction on the whole grid's model runs on one process");
  });
  Timer clock;
  PhaseTimes times;
  cli::RankInput in =
      cli::read_mesh_on_ranks(comm, app, args.input, args.in.read_options(), target_ghost_layers);
  if (!args.in.fractions.labels.empty())
    args.in.fractions.label_values = cli::grid_labels(comm, app, args.in, args.input, in);
  HeldPart part;
  cli::on_every_rank(comm, app, [&] {
    // A rank adapts the cells it read: its own and the ghost layers around them.
    const index_t cells = in.data.n_cells();
    cli::check_memory(
        "adapting " + std::to_string(cells) + " cells on rank " + std::to_string(comm.rank()),
        static_cast<double>(cells) * cli::adapt_bytes_per_cell, common.memory_limit());
    part = in.structured ? slab_part(in, args) : mesh_part(in, args);
  });
  part.cell_owner = cell_owners(comm, in);
  cli::on_every_rank(comm, app, [&] { part_targets(comm, part, options); });
  options.boundary.frozen = part.frozen;
  options.ranks = rank_decisions(comm, part, in.slab.block);
  options.progress = comm.rank() == 0 ? cli::terminal_progress(common) : nullptr;
  times.emplace_back("read", clock.seconds());
  clock.restart();
  // The cells around the cuts pillowed, unless the mending ran out of runs, or the ranks
  // holding a cut's nodes laid different layers around them, or placed their copies too far
  // apart to take each other's points: then left unpillowed.
  AnyRankMesh mesh;
  std::vector<std::int64_t> bad;
  std::vector<CellFailure> worst_input;  // of the ranks that stopped on their input
  bool stopped = false, pillowed = false;
  for (const bool pillow : {true, false}) {
    options.boundary.pillow_frozen = pillow;
    mesh = AnyRankMesh();  // a first run's part is not kept through the second
    AnyAdaptResult result;
    cli::on_every_rank(comm, app,
                       [&] { result = adapt(part.read, options, nullptr, &part.targets); });
    stopped = stopped_on_input(comm, result, part, in.slab.block, bad, worst_input);
    std::visit([&](auto& r) { mesh = rank_mesh(comm, std::move(r), part, in.slab.block); }, result);
    if (stopped) break;
    pillowed = pillow && std::visit(
                             [&](auto& m) {
                               return mended(comm, m.part.result, options) &&
                                      cli::share_nodes(comm, m.part.result, m.shared, options) &&
                                      cli::parts_meet(comm, m.part.result.mesh, m.shared,
                                                      m.part.cut_faces, m.across);
                             },
                             mesh);
    if (pillowed || !pillow) break;
  }
  part.read = AssignedGrid();
  const double adapt_seconds = clock.seconds();
  times.emplace_back("adapt", adapt_seconds);
  if (!stopped) {
    clock.restart();
    std::visit(
        [&](auto& m) {
          cli::resume_across_cuts(comm, m.part.result, m.shared, cut_rings, options);
        },
        mesh);
    times.emplace_back("cuts", clock.seconds());
  }

  std::vector<double> figures;
  Json failures, steps;
  io::MeshData piece;
  std::vector<std::pair<index_t, index_t>> shared;  // counted by higher ranks, for --gather
  std::visit(
      [&](auto& m) {
        const auto& r = m.part.result;
        figures = rank_figures(r, m.counted, part.own_cells, adapt_seconds);
        // The ranks that did not stop adapted their slabs: their cells are not the grid's.
        failures = stopped ? failures_json(worst_input, options.threshold)
                           : rank_failures(comm, r.failures, r.mesh.n_cells(), options.threshold);
        steps = all_ranks(comm, {{"layers", to_string(r.layers)},
                                 {"mend_failing", r.mend_failing},
                                 {"interface_layer_cells", r.n_interface_layer_cells},
                                 {"cavities_published", r.n_cavities_published}});
        if (stopped) return;
        piece = adapt_mesh_data(r, part.names);
        if (args.gather) shared = cli::nodes_counted_above(comm, m.shared);
      },
      mesh);
  mesh = AnyRankMesh();
  Json per_rank;
  const Json combined = combined_result(dist::all_gather_values(comm, figures), per_rank);
  Json report = report_start(app, args, common, options, part.names);
  report["result"] = combined;
  report["result"]["failures"] = failures;
  report["result"]["input_cells_below_threshold"] = bad.size();
  if (comm.rank() != 0) common.json.clear();  // rank 0 writes the report (and logs)
  std::sort(bad.begin(), bad.end());
  if (stopped) {
    report["ranks"] = cli::ranks_json(comm, in);
    return refuse_bad_input(common, report, times, bad,
                            failures_text(worst_input, options.threshold), options.threshold);
  }
  clock.restart();
  for (auto& kv : cli::provenance(app)) piece.metadata.push_back(kv);
  cli::pass_input_record(part.input, piece);
  if (args.gather) cli::drop_next_piece_nodes(piece, shared);
  cli::write_disjoint_pieces(comm, app, piece, common.output, args.gather, common.write_options(),
                             common.memory_limit());
  times.emplace_back("write", clock.seconds());
  report["ranks"] = cli::ranks_json(comm, in);
  report["ranks"].update(per_rank);
  report["ranks"]["runs"] = steps;
  // In 2D the layers are cavities, and no cavity holds a cut's node: nothing is laid across.
  report["ranks"]["cut_layers"] = !pillowed           ? "unpillowed"
                                  : in.shape.dim == 2 ? "none"
                                                      : "pillowed";
  const auto below = combined["cells_below_threshold"].get<std::int64_t>() +
                     combined["cells_below_min_edge"].get<std::int64_t>();
  report["threshold_met"] = below == 0;
  report["exit_code"] = below == 0 ? cli::ok : cli::target_missed;
  report["times"] = cli::phase_times_json(times);
  cli::write_report(common, report);
  const auto n_blocked = combined["blocked_nodes"].get<std::int64_t>();
  const auto n_frozen = combined["frozen_blocked_nodes"].get<std::int64_t>();
  if (n_blocked > 0)
    log_warning(std::to_string(n_blocked) + " of " +
                std::to_string(combined["interface_nodes"].get<std::int64_t>()) +
                " interface nodes ended off their interface" +
                (n_frozen > 0
                     ? ", " + std::to_string(n_frozen) + " of them held on the cuts between ranks"
                     : ""));
  if (below > 0) {
    log_warning(std::to_string(below) + " output cells fail the threshold " +
                std::to_string(options.threshold) + " or the size criterion\nmesh written to " +
                common.output);
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
  app.add_flag("--gather", args.gather,
               "Under mpirun on several ranks: write one file of the whole mesh (any format) "
               "instead of a .vtu piece per rank and the .pvtu naming them");
  return cli::run_on_ranks(app, argc, argv, common, [&](const dist::Communicator& comm) {
    return comm.size() > 1 ? run_adapt_on_ranks(app, args, common, comm)
                           : run_adapt(app, args, common);
  });
}
