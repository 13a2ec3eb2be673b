// The guaranteed-quality pipeline (paper Fig. 10-b and 18-d, sec. 5.1-5.3): every step only
// makes moves that keep the cells around a node at or above the threshold S_q, so the output
// holds the threshold the user gave whenever the input does. Beside a cell below it (a first
// layer kept with its failing cells, first_layer), no move makes a passing cell fail nor the
// controlled move a failing one worse; a run that still ends with such a cell is discarded.
// The target correction (sec. 5.3) and the spacing of targets closer than the size criterion
// allows (target_spacing.h) change targets only, never the mesh, so they cannot break the
// guarantee. Between the first controlled move and the move-smooth loop, cavities are
// pillowed around the nodes the move left short of their targets (sec. 5.2,
// cavity_pillow.h). After the loop, the nodes still off their surface go onto it where the
// nodes around them can repair their cells (reach_surface.h), and the loop resumes; the few
// nodes still short of their targets then get cavities (late_cavities). Those still off their
// surface at the end are reported as blocked.
#include "guaranteed_pipeline.h"

#include <algorithm>
#include <optional>
#include <string>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/adapt/reach_surface.h"
#include "hexadapt/adapt/warm_start.h"
#include "hexadapt/core/error.h"
#include "pipeline_steps.h"

namespace hexadapt::detail {

namespace {

template <class M>
std::vector<Vec3> points_of(const M& mesh) {
  std::vector<Vec3> p;
  p.reserve(static_cast<std::size_t>(mesh.n_nodes()));
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) p.push_back(mesh.point(v));
  return p;
}

template <class M>
void set_points(M& mesh, const std::vector<Vec3>& p) {
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) mesh.set_point(v, p[v.idx()]);
}

// Which layers a resolved strategy makes.
bool pillows_first(LayerStrategy s) {
  return s == LayerStrategy::first || s == LayerStrategy::both;
}
bool pillows_cavities(LayerStrategy s) {
  return s == LayerStrategy::cavities || s == LayerStrategy::both;
}

// The input cell (node) of each cell (node) of a mesh made from one whose cells (nodes) came
// from `origin`, `step` giving the one of that mesh each comes from.
template <class Id>
IdVector<Id, Id> composed(const IdVector<Id, Id>& origin, const IdVector<Id, Id>& step) {
  IdVector<Id, Id> out;
  for (Id c : step) out.push_back(origin[c]);
  return out;
}

// Nodes appended by a pillowing get no target.
template <class M>
void extend_targets(const M& mesh, Targets& targets) {
  const auto n = static_cast<std::size_t>(mesh.n_nodes());
  targets.has.reserve(n);
  targets.position.reserve(n);
  targets.interface.reserve(n);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (v.idx() < targets.has.size()) continue;
    targets.has.push_back(0);
    targets.position.push_back(mesh.point(v));
    targets.interface.push_back(NodeConstraint{});
  }
}

// Smoothing moves only the nodes without a target: nodes on their targets stay (sec. 5.1),
// and letting the blocked ones slide along their interface drew them away from their
// targets faster than the next move brought them back (dist never went down on the test
// cases).
IdVector<NodeId, char> loop_movable(const Targets& targets) {
  IdVector<NodeId, char> movable(targets.has.size(), 1);
  for (NodeId v : id_range<NodeId>(static_cast<index_t>(targets.has.size())))
    movable[v] = !targets.has[v];
  return movable;
}

// The smoothing's unsettled nodes plus every node sharing a cell with a node that moved
// since `before` (sorted, unique): what a smoothing of all nodes would try and possibly move.
template <class M>
std::vector<NodeId> nodes_around_moves(const M& mesh, const std::vector<Vec3>& before,
                                       std::vector<NodeId> nodes) {
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (mesh.point(v) == before[v.idx()]) continue;
    for (CellId c : mesh.node_cells(v))
      for (NodeId o : mesh.cell_nodes(c)) nodes.push_back(o);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// Sum of the distances to the surfaces and to the targets.
template <class M>
double distance_sums(const M& mesh, const Targets& targets,
                     const IdVector<NodeId, NodeConstraint>& sliding) {
  return surface_distance_sum(mesh, targets, sliding) + target_distance(mesh, targets);
}

// Controlled moves alternating with quality-preserving smoothing until a round no longer
// brings the nodes closer to their interface surfaces by more than the tolerance; keeps the
// best round (each reported as "move-smooth k", k counted after `rounds_before`). Nodes that
// slid onto their surface still try their target each round: moving only the nodes off their
// surface was three times faster in 3D, but left the 2D cases' discrepancy 9 % higher and
// ten times the distance to the targets. With `to_targets`, progress is the surface distance
// plus the distance to the targets, so that a round taking nodes along their surface to their
// targets is kept.
template <class M>
int move_smooth_loop(M& mesh, const Targets& targets,
                     const IdVector<NodeId, NodeConstraint>& sliding, const SizeCriterion& size,
                     const AdaptOptions& options, int rounds_before = 0,
                     const std::vector<NodeId>* first = nullptr, bool to_targets = false) {
  auto measure = [&] {
    return to_targets ? distance_sums(mesh, targets, sliding)
                      : surface_distance_sum(mesh, targets, sliding);
  };
  double best = measure();
  std::vector<Vec3> best_points = points_of(mesh);
  const IdVector<NodeId, char> movable = loop_movable(targets);
  int loops = 0;
  // What the next smoothing must try; the first tries `first`, or all without it.
  std::vector<NodeId> start = first ? *first : std::vector<NodeId>{};
  NeighbourCache neighbours(mesh.n_nodes());
  SmoothOptions smoothing = options.smooth;
  if constexpr (M::dim == 3) smoothing.min_move = options.loop_min_move;
  while (loops < options.max_loops && best > 0) {
    if (options.progress)
      options.progress("move-smooth " + std::to_string(rounds_before + loops + 1),
                       static_cast<double>(loops) / options.max_loops);
    ++loops;
    const SmoothResult s = smooth(mesh, movable, sliding, smoothing,
                                  loops == 1 && !first ? nullptr : &start, size, &neighbours);
    const std::vector<Vec3> before = points_of(mesh);
    controlled_move(mesh, targets, options.move, options, size, &sliding);
    start = nodes_around_moves(mesh, before, s.unsettled);
    const double dist = measure();
    const bool better = dist < best;
    if (better) best_points = points_of(mesh);
    const bool enough = best - dist > options.loop_tolerance * best;
    if (better) best = dist;
    if (!enough) break;
  }
  set_points(mesh, best_points);
  return loops;
}

// Pillows cavities around the nodes the first move left short of their targets (sec. 5.2),
// those that slid onto their surface too: seeded with the nodes off their surface only, the 2D
// cases kept slid nodes away from their targets (damBreak t = 0.4: target distance ratio 0.446,
// against 0 with them). Input nodes keep their ids and their targets: a seed stays with the
// cells outside its cavity, on the interface; its copies inside the cavity are new nodes
// without a target, free to smooth. The layer cells take the local size of their cavity's cells.
template <class M>
std::vector<NodeId> pillow_cavities(M& mesh, CellMaterials& material, Targets& targets,
                                    SizeCriterion& size, const MoveResult& first, int n_materials,
                                    AdaptResult<M>& r, const AdaptOptions& options) {
  std::vector<NodeId> seeds;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (targets.has[v] && !first.reached[v]) seeds.push_back(v);
  if (seeds.empty() || options.cavity.range < 1 || !pillows_cavities(r.layers)) return {};
  CavityResult<M> c =
      cavity_pillow(mesh, material, n_materials, seeds, options.cavity, options, size);
  size = size.remapped(c.cell_origin.raw());
  r.cavities = std::move(c.attempts);
  r.n_cavities_published = c.n_published;
  r.n_cells_added = c.n_cells_added;
  r.cell_origin = composed(r.cell_origin, c.cell_origin);
  r.node_origin = composed(r.node_origin, c.node_origin);
  mesh = std::move(c.mesh);
  material = std::move(c.material);
  extend_targets(mesh, targets);
  return c.failed_seeds;
}

// Rounds of the move-smooth loop after the late cavities (late_cavities).
constexpr int late_loops = 3;

// At the end of a run: cavities around the nodes still short of their targets, when they are
// at most late_cavity_share of the interface nodes, then rounds of the loop that count the
// distance to the targets; kept only when that brings the nodes closer. The extruded cases'
// first layer and a 2D case's cavities end with a few nodes on their surface short of their
// targets, which these cavities let reach them; on curved 3D surfaces hundreds are, and
// cavities around them brought them barely closer at 1.5 times the time (docs/results.md).
template <class M>
void late_cavities(M& mesh, CellMaterials& material, Targets& targets, SizeCriterion& size,
                   IdVector<NodeId, NodeConstraint>& sliding, int n_materials, AdaptResult<M>& r,
                   const AdaptOptions& options) {
  std::vector<NodeId> seeds;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (targets.has[v] && mesh.point(v) != targets.position[v]) seeds.push_back(v);
  LateCavities& late = r.late_cavities;
  late = {static_cast<index_t>(seeds.size()), false, 0, false};
  const double most = options.late_cavity_share * static_cast<double>(targets.n_interface_nodes);
  if (seeds.empty() || static_cast<double>(seeds.size()) > most || options.cavity.range < 1) return;
  late.tried = true;
  CavityResult<M> c =
      cavity_pillow(mesh, material, n_materials, seeds, options.cavity, options, size);
  late.published = c.n_published;
  if (c.n_published == 0) return;
  Targets t = targets;
  extend_targets(c.mesh, t);
  SizeCriterion s = size.remapped(c.cell_origin.raw());
  auto sl = sliding_constraints(boundary_constraints(c.mesh, options.boundary), t);
  AdaptOptions rounds = options;
  rounds.max_loops = std::min(late_loops, options.max_loops - r.loops);
  const int loops = move_smooth_loop(c.mesh, t, sl, s, rounds, r.loops, nullptr, true);
  if (distance_sums(c.mesh, t, sl) >= distance_sums(mesh, targets, sliding)) return;
  late.kept = true;
  r.loops += loops;
  r.cavities.insert(r.cavities.end(), c.attempts.begin(), c.attempts.end());
  r.n_cavities_published += c.n_published;
  r.n_cells_added += c.n_cells_added;
  r.cell_origin = composed(r.cell_origin, c.cell_origin);
  r.node_origin = composed(r.node_origin, c.node_origin);
  mesh = std::move(c.mesh);
  material = std::move(c.material);
  targets = std::move(t);
  size = std::move(s);
  sliding = std::move(sl);
}

// What the first controlled move leaves, with or without the interfaces pillowed first
// (interface_pillow.h: the interface nodes keep their ids and targets, the new nodes have
// none; the layer cells take their region's local size).
template <class M>
struct FirstMove {
  M mesh;
  CellMaterials material;
  Targets targets;
  SizeCriterion size;
  MoveResult move;
  std::vector<InterfacePillowAttempt> pillows;
  IdVector<CellId, CellId> cell_origin;  ///< the input cell each cell comes from
  IdVector<NodeId, NodeId> node_origin;  ///< the input node each node is (a copy of)
  BoundaryOptions boundary;  ///< on mesh: with pillow_frozen, frozen nodes' copies frozen too
  index_t layer_cells = 0;
  double surface_dist = 0;  ///< sum of surface distances after the move
  double pillow_seconds = 0, move_seconds = 0;
};

// `mend`, when given: the layers are kept with their failing cells (interface_pillow.h), left
// out around these input cells.
template <class M>
FirstMove<M> first_move(const M& mesh, const CellMaterials& material, const Targets& targets,
                        const SizeCriterion& size, bool pillow_first, int n_materials,
                        const AdaptOptions& options, const std::vector<CellId>* mend) {
  // The input is pillowed as it is: a copy of it would be held beside the pillowed mesh.
  FirstMove<M> f{M(), {}, targets, size, {}, {}, {}, {}, options.boundary, 0, 0, 0, 0};
  if (options.progress) options.progress("pillow", 0.0);
  Timer clock;
  if (pillow_first && options.interface_pillow.rounds > 0) {
    InterfacePillowOptions io = options.interface_pillow;
    io.keep_failing = mend != nullptr;
    InterfacePillowResult<M> p =
        pillow_interfaces(mesh, material, n_materials, targets.has, size, io, options,
                          mend ? *mend : std::vector<CellId>{});
    f.pillows = std::move(p.attempts);
    f.layer_cells = p.mesh.n_cells() - mesh.n_cells();
    f.size = f.size.remapped(p.cell_origin.raw());
    f.cell_origin = std::move(p.cell_origin);
    f.node_origin = std::move(p.node_origin);
    f.mesh = std::move(p.mesh);
    f.material = std::move(p.material);
    extend_targets(f.mesh, f.targets);
    f.boundary = options.boundary.on_copies(f.node_origin);
  } else {
    f.mesh = mesh;
    f.material = material;
    for (CellId c : id_range<CellId>(mesh.n_cells())) f.cell_origin.push_back(c);
    for (NodeId v : id_range<NodeId>(mesh.n_nodes())) f.node_origin.push_back(v);
  }
  f.pillow_seconds = clock.seconds();
  if (options.progress) options.progress("move", 0.2);
  clock.restart();
  const auto sliding = sliding_constraints(boundary_constraints(f.mesh, f.boundary), f.targets);
  f.move = controlled_move(f.mesh, f.targets, options.move, options, f.size, &sliding);
  f.surface_dist = surface_distance_sum(f.mesh, f.targets, sliding);
  f.move_seconds = clock.seconds();
  return f;
}

// Sec. 5.3: smooths the targets on the model in 3D; says why when it does not run.
template <class M>
void correct(const M& mesh, const CellMaterials& material,
             const IdVector<NodeId, NodeConstraint>& boundary, Targets& targets,
             const reconstruct::InterfaceModel* model, AdaptResult<M>& r, Timer& clock,
             const AdaptOptions& options) {
  if (!options.correction.enabled) {
    r.correction.skipped = "disabled";
  } else if constexpr (M::dim != 3) {
    r.correction.skipped = "2D (the correction is 3D only)";
  } else if (!model) {
    r.correction.skipped = "no model given";
  } else {
    if (options.progress) options.progress("correct", 0.1);
    TargetCorrectionOptions correction = options.correction;
    correction.poor_below = options.threshold;
    r.correction = correct_targets(mesh, material, boundary, *model, targets, correction);
    if (r.correction.ran) record_step(r, mesh, "correct", clock, options.progress, 0.15, "layers");
  }
}

// Marks the nodes left short of their targets and collects the worst cells around them.
template <class M>
void diagnose(AdaptResult<M>& r, const std::vector<NodeId>& failed_seeds) {
  const M& mesh = r.mesh;
  r.blocked.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
  std::vector<std::pair<CellId, double>> cells;
  IdVector<CellId, char> seen(static_cast<std::size_t>(mesh.n_cells()), 0);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (!r.has_target[v] || r.near_interface[v]) continue;
    r.blocked[v] = static_cast<char>(std::binary_search(failed_seeds.begin(), failed_seeds.end(), v)
                                         ? BlockReason::cavity
                                         : BlockReason::quality);
    ++r.n_blocked;
    for (CellId c : mesh.node_cells(v))
      if (!seen[c]) {
        seen[c] = 1;
        cells.emplace_back(c, mesh.cell_quality(c));
      }
  }
  std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) {
    return a.second < b.second || (a.second == b.second && a.first < b.first);
  });
  if (cells.size() > 10) cells.resize(10);
  r.blocking_cells = std::move(cells);
}

// Rounds of the move-smooth loop after the reach step. Measured on the vortex 64^3 at t = 1.5
// (target distance ratio; CPU s of the step and the rounds): 0.54 after the step, 0.376 after
// 1 round (0.7 s), 0.343 after 3 (1.0 s), 0.337 after the 7 rounds left of 20 (1.5 s), 0.31
// without the step. The rounds cost adapt's speed on the vortex, whose margin is thin.
constexpr int resumed_loops = 1;

// Rounds of the move-smooth loop after which a run whose first layer was kept failing is
// judged (run_layers). Measured at 48^3 on venn and balldrop t = 1: the cells failing after
// 2-3 rounds are those failing at the end, or one more. Judged after 1 round (with the
// layers left out of the failing cells only and the copies dragged along), balldrop 40^3 at
// t = 1 takes 3 runs instead of 4 and the vortex 64^3 at t = 1.5 4 instead of 7 (CPU s,
// back to back: 11.8 -> 8.6 and 43.8 -> 24.9), with 99.1 and 98.1 % of their nodes near
// instead of 99.2 and 98.4 %.
constexpr int mend_probe_loops = 1;

// Smooths the nodes of the cells around every cell below a criterion, those with a target
// too, sliding on their interface surfaces (so they stay near them), each trying the pattern
// search: the move-smooth loop holds the nodes with a target at their targets, where a layer
// cell sheared on the staircase may stay failing. No passing cell fails (the floor).
template <class M>
void smooth_around_failing(M& mesh, const IdVector<NodeId, NodeConstraint>& sliding,
                           const SizeCriterion& size, const AdaptOptions& options) {
  IdVector<NodeId, char> movable(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (const CellFailure& f : failing_cells(mesh, options.threshold, size))
    for (NodeId v : mesh.cell_nodes(f.cell))
      for (CellId c : mesh.node_cells(v))
        for (NodeId w : mesh.cell_nodes(c)) movable[w] = 1;
  SmoothOptions o = options.smooth;
  o.optimise_below = 1.0;
  smooth(mesh, movable, sliding, o, nullptr, size);
}

// The input cells the cells below a criterion come from, increasing.
template <class M>
std::vector<CellId> failing_origins(const M& mesh, const IdVector<CellId, CellId>& origin,
                                    const SizeCriterion& size, double threshold) {
  std::vector<CellId> out;
  for (const CellFailure& f : failing_cells(mesh, threshold, size)) out.push_back(origin[f.cell]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// A run of the mending (first_layer). In: the input cells around which no layer goes, and
// where the run before ended (none for the first run). Out: the input cells of the cells this
// run left failing, and where it ended.
struct Mend {
  std::vector<CellId> cells;
  NodePlaces places;
};

// The steps after the targets, with the given (resolved) layer strategy: the first move
// (after a first layer, for `first` and `both`), cavities (for `cavities` and `both`), the
// move-smooth loop; fills r. `mend`, when given (a first layer only): the layers are kept
// with their failing cells (first_move); the run starts where the run before ended
// (warm_start.h), and is judged after a few rounds of the loop.
template <class M>
void run_layers(const M& grid, const CellMaterials& material, const Targets& grid_targets,
                const SizeCriterion& grid_size, int n_materials, LayerStrategy layers,
                AdaptResult<M>& r, const AdaptOptions& given, Mend* mend = nullptr) {
  r.layers = layers;
  FirstMove<M> f = first_move(grid, material, grid_targets, grid_size, pillows_first(layers),
                              n_materials, given, mend ? &mend->cells : nullptr);
  AdaptOptions options = given;  // the steps after the layers hold the frozen nodes' copies
  options.boundary = std::move(f.boundary);
  M mesh = std::move(f.mesh);
  r.cell_origin = f.cell_origin;
  r.node_origin = f.node_origin;
  IdVector<CellId, int> out_material = std::move(f.material);
  Targets targets = std::move(f.targets);
  SizeCriterion size = std::move(f.size);
  r.interface_pillows = std::move(f.pillows);
  r.n_interface_layer_cells = f.layer_cells;
  r.dist_init = f.move.dist;
  r.surface_dist_init = f.surface_dist;
  const MoveResult first = std::move(f.move);
  // Both steps report the moved mesh's quality: the pillowed one before the move is not kept.
  const double moved_quality = min_quality(mesh);
  r.steps.push_back({"pillow", moved_quality, mesh.n_cells(), f.pillow_seconds});
  r.steps.push_back({"move", moved_quality, mesh.n_cells(), f.move_seconds});
  Timer clock;
  if (options.progress) options.progress("cavity", 0.3);

  const std::vector<NodeId> failed =
      pillow_cavities(mesh, out_material, targets, size, first, n_materials, r, options);
  record_step(r, mesh, "cavity", clock, options.progress, 0.4, "");  // the loop reports
  // The loop's rounds report within what is left of the run (after a probe, its second half).
  AdaptOptions rest = options;
  rest.progress = progress_part(options.progress, 0.4, 0.9);

  auto sliding = sliding_constraints(boundary_constraints(mesh, options.boundary), targets);
  if (mend) {
    // No cell starts failing on the way, and what still fails after a few rounds of the loop
    // and the local smoothing is what fails at the end: a run to be discarded stops there.
    if (pillows_cavities(layers)) throw InternalError("mending a first layer with cavities");
    AdaptOptions probe = options;
    probe.max_loops = std::min(options.max_loops, mend_probe_loops);
    probe.progress = progress_part(options.progress, 0.4, 0.5);
    const bool warm = !mend->places.empty();
    const std::vector<NodeId> start =
        warm ? warm_start(mesh, node_places(mesh, f.node_origin, f.cell_origin), mend->places)
             : std::vector<NodeId>{};
    r.loops = move_smooth_loop(mesh, targets, sliding, size, probe, 0, warm ? &start : nullptr);
    if (options.progress) options.progress("mend", 0.5);
    smooth_around_failing(mesh, sliding, size, options);
    mend->cells = failing_origins(mesh, f.cell_origin, size, options.threshold);
    if (!mend->cells.empty()) {
      mend->places = node_places(mesh, f.node_origin, f.cell_origin);
      record_step(r, mesh, "move-smooth", clock, options.progress, 1.0, "");
      return;  // the caller discards the run
    }
    rest.progress = progress_part(options.progress, 0.5, 0.9);
  }
  rest.max_loops = options.max_loops - r.loops;
  r.loops += move_smooth_loop(mesh, targets, sliding, size, rest, r.loops);
  record_step(r, mesh, "move-smooth", clock, options.progress, 0.9, "reach");
  const std::vector<Vec3> before_reach = points_of(mesh);
  r.reach = reach_surfaces(mesh, targets, sliding, size, options.reach, options.smooth,
                           options.threshold, options.near_interface);
  if (r.reach.moves > 0) {
    // The loop resumes around what the step moved: the nodes the repairs slid along their
    // surfaces go back toward their targets.
    rest.max_loops = std::min(resumed_loops, options.max_loops - r.loops);
    rest.progress = progress_part(options.progress, 0.95, 1.0);
    const std::vector<NodeId> around = nodes_around_moves(mesh, before_reach, {});
    r.loops += move_smooth_loop(mesh, targets, sliding, size, rest, r.loops, &around);
  }
  record_step(r, mesh, "reach", clock, options.progress, 1.0, "");
  rest.max_loops = options.max_loops;  // late_cavities counts the rounds already run
  late_cavities(mesh, out_material, targets, size, sliding, n_materials, r, rest);
  record_step(r, mesh, "late-cavity", clock, options.progress, 1.0, "");
  r.late_reach =
      reach_targets(mesh, targets, sliding, size, options.reach, options.smooth, options.threshold);
  record_step(r, mesh, "late-reach", clock, options.progress, 1.0, "");

  r.mesh = std::move(mesh);
  r.material = std::move(out_material);
  finish_result(r, targets.position, targets.has, size, &sliding, options);
  diagnose(r, failed);
}

// A first layer (LayerStrategy::first): kept with its failing cells for the moves and
// smooth_around_failing to mend, left out around the input cells whose cells the run before
// left failing, at most mend_rounds times; when no such run ends with every cell passing, the
// layers carved where their cells fail before the move, which keeps the guarantee. The
// discarded runs' time is the step "mend". Each run starts where the run before ended, but
// around what it leaves out: on the vortex 64^3 at t = 1.5 (4 runs), the runs after the first
// started from 7483, 4764 and 499 nodes instead of all, and the whole adapt took 16.7 % fewer
// instructions (callgrind), with as many nodes near their surface.
template <class M>
AdaptResult<M> first_layer(const M& grid, const CellMaterials& material, const Targets& targets,
                           const SizeCriterion& size, int n_materials, const AdaptResult<M>& before,
                           const AdaptOptions& options) {
  std::vector<CellId> left_out;
  std::vector<index_t> failing;
  double seconds = 0;
  auto finish = [&](AdaptResult<M> r) {
    r.mend_failing = failing;
    if (seconds > 0) r.steps.push_back({"mend", r.min_quality, r.mesh.n_cells(), seconds});
    return r;
  };
  // Each run reports in half of the progress left, as the run that ends the mending may be any.
  double from = 0;
  auto run_options = [&](int run, double to) {
    AdaptOptions o = options;
    o.progress = progress_part(options.progress, from, to, "run " + std::to_string(run) + ": ");
    from = to;
    return o;
  };
  NodePlaces places;
  for (int round = 0; round < options.mend_rounds; ++round) {
    AdaptResult<M> r = before;
    Mend mend{left_out, std::move(places)};
    run_layers(grid, material, targets, size, n_materials, LayerStrategy::first, r,
               run_options(round + 1, 0.5 * (1 + from)), &mend);
    failing.push_back(static_cast<index_t>(mend.cells.size()));
    const bool some_failing =
        options.ranks.left_out ? options.ranks.left_out(mend.cells) : !mend.cells.empty();
    if (!some_failing) return finish(std::move(r));
    for (std::size_t k = before.steps.size(); k < r.steps.size(); ++k)
      seconds += r.steps[k].seconds;
    places = std::move(mend.places);
    left_out.insert(left_out.end(), mend.cells.begin(), mend.cells.end());
    std::sort(left_out.begin(), left_out.end());
    left_out.erase(std::unique(left_out.begin(), left_out.end()), left_out.end());
  }
  AdaptResult<M> r = before;
  run_layers(grid, material, targets, size, n_materials, LayerStrategy::first, r,
             run_options(options.mend_rounds + 1, 1.0));
  return finish(std::move(r));
}

// The frozen interface nodes' targets as computed without the freeze (frozen nodes counted
// at them in each material's volume), in node order.
struct FrozenAims {
  std::vector<NodeId> nodes;
  std::vector<Vec3> position;
  std::vector<NodeConstraint> interface;
};

// Puts every frozen node's target on the node itself, so that no step moves it; returns
// where the frozen interface nodes would go, or none when nothing is frozen.
template <class M>
std::optional<FrozenAims> hold_frozen(const M& grid, Targets& targets,
                                      const AdaptOptions& options) {
  if (options.boundary.frozen.empty()) return std::nullopt;
  FrozenAims aims;
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) {
    if (!options.boundary.is_frozen(v)) continue;
    if (targets.has[v]) {
      aims.nodes.push_back(v);
      aims.position.push_back(targets.position[v]);
      aims.interface.push_back(targets.interface[v]);
    }
    targets.position[v] = grid.point(v);
  }
  return aims;
}

// Counts the frozen nodes against their aims: a frozen interface node off its interface is
// blocked (BlockReason::frozen) and its distances are the ones it would have had to go.
template <class M>
void account_frozen(AdaptResult<M>& r, const M& grid, const FrozenAims& aims,
                    const AdaptOptions& options) {
  const auto free_boundary = boundary_constraints(grid, options.boundary.without_frozen());
  SizeCriterion size;
  size.local_size = std::move(r.local_size);
  for (std::size_t k = 0; k < aims.nodes.size(); ++k) {
    // A grid node no step moved: its target in the run was its own position.
    const NodeId v = aims.nodes[k];
    const Vec3 p = r.mesh.point(v);
    NodeConstraint surface = free_boundary[v];
    surface.add(aims.interface[k]);
    const double d = (p - aims.position[k]).norm();
    const double sd = surface_distance(p, aims.position[k], surface);
    r.target[v] = aims.position[k];
    r.distance[v] = d;
    r.surface_distance[v] = sd;
    r.dist_init += d;
    r.dist_final += d;
    r.surface_dist_init += sd;
    r.surface_dist_final += sd;
    r.n_reached -= d != 0;
    const double h = node_local_size(r.mesh, v, size);
    if (sd <= options.near_interface * h) continue;
    r.near_interface[v] = 0;
    --r.n_near_interface;
    r.blocked[v] = static_cast<char>(BlockReason::frozen);
    ++r.n_blocked;
    ++r.n_frozen_blocked;
    if (sd > r.farthest_distance) {
      r.farthest = v;
      r.farthest_distance = sd;
      r.farthest_local_size = h;
    }
  }
  r.local_size = std::move(size.local_size);
}

// The options as the steps take them: no smoothing sinks a cell below the threshold.
AdaptOptions with_shared_settings(AdaptOptions o) {
  o.smooth.floor = o.threshold;
  return o;
}

}  // namespace

template <class M>
AdaptResult<M> run_guaranteed_pipeline(const M& grid, const Fractions& fractions,
                                       const CellMaterials& material, const AdaptOptions& given,
                                       const reconstruct::InterfaceModel* model,
                                       std::optional<Targets> given_targets) {
  const AdaptOptions options = with_shared_settings(given);
  if (options.progress) options.progress("check", 0.0);
  AdaptResult<M> r;
  Timer clock;
  SizeCriterion size = size_criterion(grid, options.min_edge);
  r.input_min_quality = min_quality(grid);
  for (const CellFailure& f : failing_cells(grid, options.threshold, size))
    r.bad_input_cells.push_back(f.cell);
  const bool good_input = r.bad_input_cells.empty();
  const auto nn = static_cast<std::size_t>(grid.n_nodes());
  // On ranks, every rank stops when one does: the others' runs would wait for its decisions.
  std::vector<double> bad_anywhere{static_cast<double>(r.bad_input_cells.size())};
  if (options.ranks.add_up) options.ranks.add_up(bad_anywhere);
  if (bad_anywhere[0] > 0 && !options.allow_bad_input) {
    r.stopped_bad_input = true;
    for (CellId c : id_range<CellId>(grid.n_cells())) r.cell_origin.push_back(c);
    for (NodeId v : id_range<NodeId>(grid.n_nodes())) r.node_origin.push_back(v);
    r.mesh = grid;
    r.material = material;
    finish_result(r, IdVector<NodeId, Vec3>(nn, Vec3::Zero()), IdVector<NodeId, char>(nn, 0), size,
                  nullptr, options);
    r.blocked.assign(nn, 0);
    return r;
  }
  record_step(r, grid, "check", clock, options.progress, 0.05, "targets");

  const auto grid_boundary = boundary_constraints(grid, options.boundary);
  Targets targets =
      given_targets
          ? std::move(*given_targets)
          : compute_targets(grid, fractions, material,
                            options.boundary.frozen.empty()
                                ? grid_boundary
                                : boundary_constraints(grid, options.boundary.without_frozen()),
                            options.targets);
  if (given_targets)
    targets.n_interface_nodes =
        static_cast<index_t>(std::count(targets.has.begin(), targets.has.end(), 1));
  const std::optional<FrozenAims> aims = hold_frozen(grid, targets, options);
  r.n_interface_nodes = targets.n_interface_nodes;
  record_step(r, grid, "targets", clock, options.progress, 0.1, "layers");
  correct(grid, material, grid_boundary, targets, model, r, clock, options);
  r.spacing = space_targets(grid, material, size, sliding_constraints(grid_boundary, targets),
                            targets, options.spacing);

  const int n_materials = fractions.n_materials();
  AdaptOptions layers = options;  // what is left reports as its part of the progress
  layers.progress = progress_part(options.progress, 0.15, 1.0);
  if (options.layers == LayerStrategy::automatic && M::dim == 3) {
    // A first layer; when it leaves more than 1 - enough_share of the interface nodes off
    // their interface, cavities too, keeping the result that brings more nodes onto it.
    layers.progress = progress_part(options.progress, 0.15, 0.75);
    AdaptResult<M> layered = first_layer(grid, material, targets, size, n_materials, r, layers);
    std::vector<double> shares{static_cast<double>(layered.n_near_interface),
                               static_cast<double>(layered.n_interface_nodes)};
    if (options.ranks.add_up) options.ranks.add_up(shares);
    if (shares[0] >= options.enough_share * shares[1]) {
      r = std::move(layered);
    } else {
      AdaptResult<M> plain = r;
      layers.progress = progress_part(options.progress, 0.75, 1.0, "cavities: ");
      run_layers(grid, material, targets, size, n_materials, LayerStrategy::cavities, plain,
                 layers);
      std::vector<double> both{static_cast<double>(layered.n_near_interface),
                               static_cast<double>(plain.n_near_interface),
                               layered.surface_dist_final, plain.surface_dist_final};
      if (options.ranks.add_up) options.ranks.add_up(both);
      const bool take = both[0] > both[1] || (both[0] == both[1] && both[2] < both[3]);
      AdaptResult<M>& other = take ? plain : layered;
      double seconds = 0;
      for (std::size_t k = r.steps.size(); k < other.steps.size(); ++k)
        seconds += other.steps[k].seconds;
      r = std::move(take ? layered : plain);
      r.other_near_interface = other.n_near_interface;
      r.steps.push_back({"other-layers", r.min_quality, r.mesh.n_cells(), seconds});
    }
  } else if (options.layers == LayerStrategy::first) {
    r = first_layer(grid, material, targets, size, n_materials, r, layers);
  } else {
    run_layers(
        grid, material, targets, size, n_materials,
        options.layers == LayerStrategy::automatic ? LayerStrategy::cavities : options.layers, r,
        layers);
  }
  if (aims) account_frozen(r, grid, *aims, options);
  if (good_input && (r.n_below_threshold > 0 || r.n_below_min_edge > 0))
    throw InternalError("guaranteed pipeline left " + std::to_string(r.n_below_threshold) +
                        " cells below the threshold " + std::to_string(options.threshold) +
                        " and " + std::to_string(r.n_below_min_edge) +
                        " below the size criterion " + std::to_string(options.min_edge));
  if (options.progress) options.progress("done", 1.0);
  return r;
}

template AdaptResult<QuadMesh> run_guaranteed_pipeline<QuadMesh>(const QuadMesh&, const Fractions&,
                                                                 const IdVector<CellId, int>&,
                                                                 const AdaptOptions&,
                                                                 const reconstruct::InterfaceModel*,
                                                                 std::optional<Targets>);
template AdaptResult<HexMesh> run_guaranteed_pipeline<HexMesh>(const HexMesh&, const Fractions&,
                                                               const IdVector<CellId, int>&,
                                                               const AdaptOptions&,
                                                               const reconstruct::InterfaceModel*,
                                                               std::optional<Targets>);

}  // namespace hexadapt::detail

namespace hexadapt {

template <class M>
ResumeResult resume_moves(M& mesh, const Targets& given_targets,
                          const IdVector<NodeId, NodeConstraint>& sliding,
                          const SizeCriterion& size, const AdaptOptions& given) {
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  if (given_targets.has.size() != nn || given_targets.position.size() != nn ||
      sliding.size() != nn || size.local_size.size() != static_cast<std::size_t>(mesh.n_cells()))
    throw InternalError("resume_moves: targets, constraints or sizes do not match the mesh");
  // A frozen node is on its target for the steps, so that none moves it (as in the pipeline).
  Targets targets = given_targets;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (sliding[v].frozen()) targets.position[v] = mesh.point(v);
  const AdaptOptions options = detail::with_shared_settings(given);
  ResumeResult r;
  r.loops = detail::move_smooth_loop(mesh, targets, sliding, size, options);
  const std::vector<Vec3> before = detail::points_of(mesh);
  r.reach = reach_surfaces(mesh, targets, sliding, size, options.reach, options.smooth,
                           options.threshold, options.near_interface);
  if (r.reach.moves > 0) {
    AdaptOptions rest = options;
    rest.max_loops = std::min(detail::resumed_loops, options.max_loops);
    const std::vector<NodeId> around = detail::nodes_around_moves(mesh, before, {});
    r.loops += detail::move_smooth_loop(mesh, targets, sliding, size, rest, r.loops, &around);
  }
  r.late_reach =
      reach_targets(mesh, targets, sliding, size, options.reach, options.smooth, options.threshold);
  return r;
}

template ResumeResult resume_moves<QuadMesh>(QuadMesh&, const Targets&,
                                             const IdVector<NodeId, NodeConstraint>&,
                                             const SizeCriterion&, const AdaptOptions&);
template ResumeResult resume_moves<HexMesh>(HexMesh&, const Targets&,
                                            const IdVector<NodeId, NodeConstraint>&,
                                            const SizeCriterion&, const AdaptOptions&);

}  // namespace hexadapt
