#include "hexadapt/adapt/reach_surface.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {

// What the nodes reach: their surface (reach_surfaces) or their target (reach_targets).
enum class Goal : char { surface, target };

// A node off its goal and the nodes that repair its cells (sorted). For the surface: the
// nodes without a target within two cells of it and the nodes with a target sharing a cell
// with it. For the target: the nodes without a target sharing a cell with it; within two
// cells, the nodes on the 3D cases reached their targets as often, at 4-5 times the time.
struct Region {
  NodeId node;
  std::vector<NodeId> helpers;
};

// The nodes off their goal: farther than near_interface local sizes from their surface, or
// anywhere but on their target.
template <class M>
std::vector<NodeId> off_goal(const M& mesh, const Targets& targets,
                             const IdVector<NodeId, NodeConstraint>& surface,
                             const SizeCriterion& size, double near_interface, Goal goal) {
  std::vector<NodeId> out;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (!targets.has[v]) continue;
    const bool off = goal == Goal::target
                         ? mesh.point(v) != targets.position[v]
                         : surface_distance(mesh.point(v), targets.position[v], surface[v]) >
                               near_interface * node_local_size(mesh, v, size);
    if (off) out.push_back(v);
  }
  return out;
}

template <class M>
Region region_of(const M& mesh, NodeId n, const Targets& targets, Goal goal) {
  Region r{n, {}};
  for (CellId c : mesh.node_cells(n))
    for (NodeId w : mesh.cell_nodes(c)) {
      if (goal == Goal::target) {
        if (!targets.has[w]) r.helpers.push_back(w);
        continue;
      }
      if (w != n && targets.has[w]) r.helpers.push_back(w);
      for (CellId d : mesh.node_cells(w))
        for (NodeId x : mesh.cell_nodes(d))
          if (!targets.has[x]) r.helpers.push_back(x);
    }
  std::sort(r.helpers.begin(), r.helpers.end());
  r.helpers.erase(std::unique(r.helpers.begin(), r.helpers.end()), r.helpers.end());
  return r;
}

// Calls f on every cell around the region's node and helpers (a cell may come more than once).
template <class M, class F>
void for_region_cells(const M& mesh, const Region& r, F f) {
  for (CellId c : mesh.node_cells(r.node)) f(c);
  for (NodeId w : r.helpers)
    for (CellId c : mesh.node_cells(w)) f(c);
}

// The regions in batches whose regions share no cell, in order: the first batch takes every
// region that shares no cell with one taken before it, the next batch the rest likewise.
template <class M>
std::vector<std::vector<const Region*>> disjoint_batches(const M& mesh,
                                                         const std::vector<Region>& regions) {
  std::vector<std::vector<const Region*>> batches;
  IdVector<CellId, char> taken(static_cast<std::size_t>(mesh.n_cells()), 0);
  std::vector<const Region*> left;
  for (const Region& r : regions) left.push_back(&r);
  while (!left.empty()) {
    std::vector<const Region*> batch, later;
    for (const Region* r : left) {
      bool free = true;
      for_region_cells(mesh, *r, [&](CellId c) { free = free && !taken[c]; });
      if (!free) {
        later.push_back(r);
        continue;
      }
      for_region_cells(mesh, *r, [&](CellId c) { taken[c] = 1; });
      batch.push_back(r);
    }
    for (const Region* r : batch) for_region_cells(mesh, *r, [&](CellId c) { taken[c] = 0; });
    batches.push_back(std::move(batch));
    left = std::move(later);
  }
  return batches;
}

template <class M>
bool region_passes(const M& mesh, const Region& r, const SizeCriterion& size, double threshold) {
  if (min_score_around(mesh, r.node, size, threshold) < threshold) return false;
  for (NodeId w : r.helpers)
    if (min_score_around(mesh, w, size, threshold) < threshold) return false;
  return true;
}

// Where a node `offset` from its goal tries to go on its k-th try: onto it, 3/4 of the way,
// then, for a surface, just within `near` of it. False: the k-th try would be no nearer than
// the one before, or is not for this goal, and is not made.
bool kth_position(const Vec3& at, const Vec3& offset, double near, int k, Goal goal, Vec3& p) {
  const double fractions[] = {1.0, 0.75, 1.0 - 0.8 * near / offset.norm()};
  if (k == 2 && (goal == Goal::target || fractions[2] >= fractions[1])) return false;
  p = at - fractions[k] * offset;
  return true;
}

// What the repairs of one call share.
template <class M>
struct Repair {
  M& mesh;
  const Targets& targets;
  const IdVector<NodeId, NodeConstraint>& surface;
  const SizeCriterion& size;
  SmoothOptions smooth;
  double threshold, near_interface;
  Goal goal;
  IdVector<NodeId, char> movable;
  NeighbourCache neighbours;
};

// One batch's k-th try: every region's node goes to its k-th position, the helpers smooth,
// and each region is kept when all its cells pass, else put back. Returns the nodes kept.
template <class M>
std::vector<NodeId> repair_batch(Repair<M>& rp, const std::vector<const Region*>& batch, int k) {
  M& mesh = rp.mesh;
  std::vector<std::vector<Vec3>> saved(batch.size());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const Region& r = *batch[i];
    const Vec3 at = mesh.point(r.node);
    const Vec3& target = rp.targets.position[r.node];
    const Vec3 offset = rp.goal == Goal::target ? Vec3(at - target)
                                                : surface_offset(at, target, rp.surface[r.node]);
    const double near = rp.near_interface * node_local_size(mesh, r.node, rp.size);
    Vec3 p;
    if (!kth_position(at, offset, near, k, rp.goal, p)) continue;
    if (k == 0 && rp.goal == Goal::target) p = target;  // exactly: on its target
    saved[i].push_back(at);
    for (NodeId w : r.helpers) saved[i].push_back(mesh.point(w));
    mesh.set_point(r.node, p);
    for (NodeId w : r.helpers) rp.movable[w] = 1;
  }
  smooth(mesh, rp.movable, rp.surface, rp.smooth, nullptr, rp.size, &rp.neighbours);
  std::vector<NodeId> kept;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    if (saved[i].empty()) continue;  // not tried
    const Region& r = *batch[i];
    for (NodeId w : r.helpers) rp.movable[w] = 0;
    if (region_passes(mesh, r, rp.size, rp.threshold)) {
      kept.push_back(r.node);
      continue;
    }
    mesh.set_point(r.node, saved[i][0]);
    for (std::size_t j = 0; j < r.helpers.size(); ++j)
      mesh.set_point(r.helpers[j], saved[i][j + 1]);
  }
  return kept;
}

// One pass over the nodes off their surface; returns how many came closer to it.
template <class M>
index_t reach_pass(Repair<M>& rp, const std::vector<NodeId>& off) {
  std::vector<Region> regions;
  for (NodeId n : off) regions.push_back(region_of(rp.mesh, n, rp.targets, rp.goal));
  index_t closer = 0;
  for (int k = 0; k < 3 && !regions.empty(); ++k) {
    std::vector<NodeId> kept;
    for (const auto& batch : disjoint_batches(rp.mesh, regions)) {
      const std::vector<NodeId> b = repair_batch(rp, batch, k);
      kept.insert(kept.end(), b.begin(), b.end());
    }
    std::sort(kept.begin(), kept.end());
    closer += static_cast<index_t>(kept.size());
    regions.erase(std::remove_if(regions.begin(), regions.end(),
                                 [&](const Region& r) {
                                   return std::binary_search(kept.begin(), kept.end(), r.node);
                                 }),
                  regions.end());
  }
  return closer;
}

template <class M>
ReachResult reach(M& mesh, const Targets& targets, const IdVector<NodeId, NodeConstraint>& surface,
                  const SizeCriterion& size, const ReachOptions& options,
                  const SmoothOptions& smooth, double threshold, double near_interface, Goal goal) {
  if (options.passes < 0)
    throw OptionError("reach passes must be at least 0, got " + std::to_string(options.passes));
  // The pattern search alone: with the Laplacian pulls too, the helpers with a target drifted
  // along their surfaces' planes, and the vortex's fluid at t = 1.5 lost 0.7 % of its
  // volume instead of 0.24 %.
  SmoothOptions s = smooth;
  s.optimise_below = 1.0;
  s.min_move = std::numeric_limits<double>::infinity();
  s.floor = threshold;
  Repair<M> rp{mesh,
               targets,
               surface,
               size,
               s,
               threshold,
               near_interface,
               goal,
               IdVector<NodeId, char>(static_cast<std::size_t>(mesh.n_nodes()), 0),
               NeighbourCache(mesh.n_nodes())};
  ReachResult out;
  std::vector<NodeId> off = off_goal(mesh, targets, surface, size, near_interface, goal);
  out.off_surface = static_cast<index_t>(off.size());
  while (out.passes < options.passes && !off.empty()) {
    ++out.passes;
    const index_t closer = reach_pass(rp, off);
    out.moves += closer;
    off = off_goal(mesh, targets, surface, size, near_interface, goal);
    if (closer == 0) break;
  }
  out.still_off = static_cast<index_t>(off.size());
  return out;
}

}  // namespace

template <class M>
ReachResult reach_surfaces(M& mesh, const Targets& targets,
                           const IdVector<NodeId, NodeConstraint>& surface,
                           const SizeCriterion& size, const ReachOptions& options,
                           const SmoothOptions& smooth, double threshold, double near_interface) {
  return reach(mesh, targets, surface, size, options, smooth, threshold, near_interface,
               Goal::surface);
}

template <class M>
ReachResult reach_targets(M& mesh, const Targets& targets,
                          const IdVector<NodeId, NodeConstraint>& surface,
                          const SizeCriterion& size, const ReachOptions& options,
                          const SmoothOptions& smooth, double threshold) {
  return reach(mesh, targets, surface, size, options, smooth, threshold, 0.0, Goal::target);
}

#define HEXADAPT_INSTANTIATE(M)                                                          \
  template ReachResult reach_surfaces<M>(                                                \
      M&, const Targets&, const IdVector<NodeId, NodeConstraint>&, const SizeCriterion&, \
      const ReachOptions&, const SmoothOptions&, double, double);                        \
  template ReachResult reach_targets<M>(                                                 \
      M&, const Targets&, const IdVector<NodeId, NodeConstraint>&, const SizeCriterion&, \
      const ReachOptions&, const SmoothOptions&, double);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
