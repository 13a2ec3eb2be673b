#include "hexadapt/adapt/target_spacing.h"

#include <algorithm>
#include <vector>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/mesh/cell_complex.h"

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

// Where material m lies around the edge e: from the centroid of the other materials' cells
// around its two nodes to that of m's (zero when one of the two is missing).
template <class M>
Vec3 material_side(const M& grid, const CellMaterials& material, const TargetEdge& e, int m) {
  std::vector<CellId> ring(grid.node_cells(e.u).begin(), grid.node_cells(e.u).end());
  for (CellId c : grid.node_cells(e.v))
    if (corner_of(grid, c, e.u) < 0) ring.push_back(c);
  Vec3 in = Vec3::Zero(), out = Vec3::Zero();
  int n_in = 0, n_out = 0;
  for (CellId c : ring) {
    const bool mine = material[c] == m;
    (mine ? in : out) += cell_centroid(grid, c);
    ++(mine ? n_in : n_out);
  }
  if (n_in == 0 || n_out == 0) return Vec3::Zero();
  return (in / n_in - out / n_out).normalized();
}

// Whether the nodes of e, both on their targets, would turn every cell of the edge inside
// out. The edge turns from its grid direction to the targets' one, and each cell from the
// edge's side it has in the grid to its material's side: the two frames (edge x side) must
// keep their orientation. Only targets closer than half the edge are judged: there, a riser
// of the staircase lying across the interface, the order of the two projections is noise.
template <class M>
bool crossed(const M& grid, const CellMaterials& material, const TargetEdge& e,
             const Targets& targets) {
  const Vec3 pu = grid.point(e.u), pv = grid.point(e.v);
  const Vec3 edge = pv - pu;
  const Vec3 reached = targets.position[e.v] - targets.position[e.u];
  if (reached.norm() >= 0.5 * edge.norm()) return false;
  int kept = 0, turned = 0;
  for (CellId c : grid.node_cells(e.u)) {
    if (corner_of(grid, c, e.v) < 0) continue;
    const Vec3 before = edge.cross(cell_centroid(grid, c) - 0.5 * (pu + pv));
    const Vec3 after = reached.cross(material_side(grid, material, e, material[c]));
    const double turn = before.dot(after);
    kept += turn > 0;
    turned += turn < 0;
  }
  return turned > 0 && kept == 0;
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
TargetSpacingResult space_targets(const M& grid, const CellMaterials& material,
                                  const SizeCriterion& size,
                                  const IdVector<NodeId, NodeConstraint>& sliding, Targets& targets,
                                  const TargetSpacingOptions& options) {
  TargetSpacingResult r;
  if (!size.on()) return r;
  const std::vector<TargetEdge> edges = target_edges(grid, size, targets);
  for (const TargetEdge& e : edges)
    if (options.uncross && crossed(grid, material, e, targets)) {
      std::swap(targets.position[e.u], targets.position[e.v]);
      ++r.swapped;
    }
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

template TargetSpacingResult space_targets<QuadMesh>(const QuadMesh&, const CellMaterials&,
                                                     const SizeCriterion&,
                                                     const IdVector<NodeId, NodeConstraint>&,
                                                     Targets&, const TargetSpacingOptions&);
template TargetSpacingResult space_targets<HexMesh>(const HexMesh&, const CellMaterials&,
                                                    const SizeCriterion&,
                                                    const IdVector<NodeId, NodeConstraint>&,
                                                    Targets&, const TargetSpacingOptions&);

}  // namespace hexadapt
