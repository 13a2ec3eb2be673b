#include "hexadapt/adapt/target_spacing.h"

#include <algorithm>
#include <vector>

#include "hexadapt/adapt/local_topology.h"

namespace hexadapt {

namespace {

// An edge between two nodes with a target and the shortest length its cells allow.
struct TargetEdge {
  NodeId u, v;  ///< u < v
  double min_length = 0;
};

template <class M>
std::vector<TargetEdge> target_edges(const M& grid, const SizeCriterion& size,
                                     const Targets& targets) {
  std::vector<TargetEdge> edges;
  for (NodeId u : id_range<NodeId>(grid.n_nodes())) {
    if (!targets.has[u]) continue;
    for (NodeId v : edge_neighbours(grid, u)) {
      if (v <= u || !targets.has[v]) continue;
      double len = 0;
      for (CellId c : grid.node_cells(u))
        if (corner_of(grid, c, v) >= 0) len = std::max(len, size.min_length(c));
      edges.push_back({u, v, len});
    }
  }
  return edges;
}

// Pushes the targets of e apart to `want`, each within its constraint and its shift budget;
// false when they cannot move apart.
bool push_apart(const TargetEdge& e, double want, const IdVector<NodeId, NodeConstraint>& sliding,
                const IdVector<NodeId, Vec3>& start, const IdVector<NodeId, double>& budget,
                Targets& targets) {
  Vec3& tu = targets.position[e.u];
  Vec3& tv = targets.position[e.v];
  const Vec3 d = tv - tu;
  const double len = d.norm();
  const Vec3 dir =
      len > 1e-12 * want ? Vec3(d / len) : Vec3((start[e.v] - start[e.u]).normalized());
  const Vec3 mu = -sliding[e.u].project(dir);
  const Vec3 mv = sliding[e.v].project(dir);
  const double rate = mv.dot(dir) - mu.dot(dir);  // separation gained per unit step
  if (rate < 1e-6) return false;
  const double step = (want - len) / rate;
  const Vec3 nu = tu + step * mu;
  const Vec3 nv = tv + step * mv;
  if ((nu - start[e.u]).norm() > budget[e.u] || (nv - start[e.v]).norm() > budget[e.v])
    return false;
  tu = nu;
  tv = nv;
  return true;
}

}  // namespace

template <class M>
TargetSpacingResult space_targets(const M& grid, const SizeCriterion& size,
                                  const IdVector<NodeId, NodeConstraint>& sliding, Targets& targets,
                                  const TargetSpacingOptions& options) {
  TargetSpacingResult r;
  if (!size.on()) return r;
  const std::vector<TargetEdge> edges = target_edges(grid, size, targets);
  const IdVector<NodeId, Vec3> start = targets.position;
  IdVector<NodeId, double> budget(start.size(), 0.0);
  for (NodeId v : id_range<NodeId>(grid.n_nodes()))
    if (targets.has[v]) budget[v] = options.max_shift * node_local_size(grid, v, size);
  auto short_of = [&](const TargetEdge& e) {
    return (targets.position[e.v] - targets.position[e.u]).norm() < e.min_length;
  };
  for (const TargetEdge& e : edges) r.short_edges += short_of(e);
  for (; r.sweeps < options.sweeps; ++r.sweeps) {
    bool pushed = false;
    for (const TargetEdge& e : edges)
      if (short_of(e))
        pushed |= push_apart(e, options.margin * e.min_length, sliding, start, budget, targets);
    if (!pushed) break;
  }
  for (const TargetEdge& e : edges) r.left_short += short_of(e);
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) {
    const double shift = (targets.position[v] - start[v]).norm();
    if (shift == 0) continue;
    ++r.moved;
    r.max_shift = std::max(r.max_shift, shift / node_local_size(grid, v, size));
  }
  return r;
}

template TargetSpacingResult space_targets<QuadMesh>(const QuadMesh&, const SizeCriterion&,
                                                     const IdVector<NodeId, NodeConstraint>&,
                                                     Targets&, const TargetSpacingOptions&);
template TargetSpacingResult space_targets<HexMesh>(const HexMesh&, const SizeCriterion&,
                                                    const IdVector<NodeId, NodeConstraint>&,
                                                    Targets&, const TargetSpacingOptions&);

}  // namespace hexadapt
