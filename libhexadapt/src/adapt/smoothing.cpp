#include "hexadapt/adapt/smoothing.h"

#include <string>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "node_scores.h"

namespace hexadapt {

namespace {

// The Laplacian displacement d of n toward the mean of `around`, within its constraint;
// false when it is shorter than min_move edge lengths: such a pull is not made, or the
// Laplacian relaxation would creep over the whole mesh for ever, moving every node by ever
// smaller amounts.
template <class M>
bool laplacian_pull(const M& mesh, NodeId n, const std::vector<NodeId>& around,
                    const NodeConstraint& constraint, const SmoothOptions& options, Vec3& d) {
  Vec3 mean = Vec3::Zero();
  for (NodeId o : around) mean += mesh.point(o);
  mean /= static_cast<double>(around.size());
  d = constraint.project(mean - mesh.point(n));
  return d.norm() > options.min_move * mean_edge_length(mesh, n, around);
}

// One node: the largest halving of the pull d that does not lower the local minimum quality.
// Returns the gain in local minimum (-1 when no halving is kept). `q`: the local minimum, on
// entry and on return; `scores`: the cells' scores at the node's position.
template <class M>
double laplacian_step(M& mesh, NodeId n, Vec3 d, const SmoothOptions& options,
                      detail::NodeScores<M>& scores, double& q) {
  const Vec3 p = mesh.point(n);
  const double before = q;
  for (int h = 0; h <= options.halvings; ++h, d *= 0.5) {
    mesh.set_point(n, p + d);
    const double after = scores.trial(before);
    if (after >= before && !scores.sinks_below(options.floor)) {
      scores.accept_trial();
      q = after;
      return after - before;
    }
  }
  mesh.set_point(n, p);
  return -1;
}

// The least rise of the local minimum the pattern search takes as an improvement.
constexpr double search_gain = 1e-9;

// Compass search on the local minimum quality: steps along +-x, +-y (+-z), projected on the
// constraint, keeping the best strict improvement, halving the step when none improves.
template <class M>
double pattern_search(M& mesh, NodeId n, const std::vector<NodeId>& around,
                      const NodeConstraint& constraint, int levels, double floor,
                      detail::NodeScores<M>& scores, double& q) {
  double h = 0.25 * mean_edge_length(mesh, n, around);
  const double start = q;
  double best = start;
  bool capped_checked = false;  // at this best
  for (int level = 0; level < levels; ++level, h *= 0.5) {
    bool improved = true;
    while (improved) {
      // A worst cell that no position of n raises (its worst corner or its shortest edge is
      // away from n) ends the search, which would try every step in vain (72 % of the
      // searches on balldrop 40^3 at t = 1.5).
      if (!capped_checked && scores.capped(best + search_gain)) {
        q = best;
        return best - start;
      }
      capped_checked = true;
      improved = false;
      const Vec3 p = mesh.point(n);
      Vec3 best_p = p;
      for (int axis = 0; axis < M::dim; ++axis)
        for (double sign : {1.0, -1.0}) {
          const Vec3 d = constraint.project(sign * h * Vec3::Unit(axis));
          if (!(d.norm() > 1e-3 * h)) continue;
          mesh.set_point(n, p + d);
          const double trial = scores.trial(best + search_gain);
          if (trial > best + search_gain && !scores.sinks_below(floor)) {
            scores.accept_trial();
            best = trial;
            best_p = p + d;
            improved = true;
            capped_checked = false;
          }
        }
      mesh.set_point(n, best_p);
    }
  }
  q = best;
  return best - start;
}

template <class M>
double smooth_node(M& mesh, NodeId n, const NodeConstraint& constraint,
                   const SmoothOptions& options, const SizeCriterion& size,
                   NeighbourCache& neighbours, detail::CellScoreCache& cache) {
  const std::vector<NodeId>& around = neighbours.of(mesh, n);
  if (around.empty()) return 0;
  double q = detail::cached_min_score(mesh, n, size, cache);
  Vec3 d;
  const bool pull = laplacian_pull(mesh, n, around, constraint, options, d);
  if (!pull && !(q < options.optimise_below)) return 0;  // nothing to try: most tries
  detail::NodeScores<M> scores(mesh, n, size, cache);
  double gain = pull ? laplacian_step(mesh, n, d, options, scores, q) : 0;
  if (q < options.optimise_below) {
    const double more = pattern_search(mesh, n, around, constraint, options.search_levels,
                                       options.floor, scores, q);
    if (more > 0) gain = std::max(gain, 0.0) + more;
  }
  scores.store(cache);
  return gain;
}

}  // namespace

template <class M>
SmoothResult smooth(M& mesh, const IdVector<NodeId, char>& movable,
                    const IdVector<NodeId, NodeConstraint>& constraint,
                    const SmoothOptions& options, const std::vector<NodeId>* start,
                    const SizeCriterion& size, NeighbourCache* neighbours) {
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  if (movable.size() != nn || constraint.size() != nn)
    throw InternalError("smoothing: movable flags or constraints do not match the mesh");
  NeighbourCache own(neighbours ? 0 : mesh.n_nodes());
  if (!neighbours) neighbours = &own;
  if (neighbours->n_nodes() != mesh.n_nodes())
    throw InternalError("smoothing: the neighbour cache does not match the mesh");
  if (options.iterations < 0 || options.halvings < 0 || !(options.min_move >= 0))
    throw OptionError("smoothing iterations, halvings and min_move must be >= 0");
  std::vector<NodeId> nodes;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (movable[n] && !constraint[n].fixed(M::dim)) nodes.push_back(n);
  const auto sets = independent_node_sets(mesh, nodes);
  // A node whose cells' nodes did not move since it was last tried would make the same
  // choice again (no move): only the nodes around a move are tried again.
  std::vector<char> active(nn, 0);
  for (NodeId n : start ? *start : nodes) active[n.idx()] = movable[n];
  detail::CellScoreCache cache(mesh.n_cells());
  SmoothResult out;
  while (out.iterations < options.iterations) {
    ++out.iterations;
    double best_gain = 0;
    for (const auto& set : sets) {
      std::vector<NodeId> todo;
      for (NodeId n : set)
        if (active[n.idx()]) todo.push_back(n);
      std::vector<double> gain(todo.size(), -1);
      std::vector<char> moved(todo.size(), 0);
      for_each_item(todo.size(), [&](std::int64_t i) {
        const auto k = static_cast<std::size_t>(i);
        const NodeId n = todo[k];
        const Vec3 before = mesh.point(n);
        gain[k] = smooth_node(mesh, n, constraint[n], options, size, *neighbours, cache);
        moved[k] = mesh.point(n) != before;
      });
      for (std::size_t k = 0; k < todo.size(); ++k) {
        out.moves += moved[k];
        best_gain = std::max(best_gain, gain[k]);
        active[todo[k].idx()] = 0;
      }
      for (std::size_t k = 0; k < todo.size(); ++k)
        if (moved[k])
          for (CellId c : mesh.node_cells(todo[k]))
            for (NodeId o : mesh.cell_nodes(c)) active[o.idx()] = movable[o] != 0;
    }
    if (best_gain <= options.min_gain) break;
  }
  for (NodeId n : nodes)
    if (active[n.idx()]) out.unsettled.push_back(n);
  return out;
}

template SmoothResult smooth<QuadMesh>(QuadMesh&, const IdVector<NodeId, char>&,
                                       const IdVector<NodeId, NodeConstraint>&,
                                       const SmoothOptions&, const std::vector<NodeId>*,
                                       const SizeCriterion&, NeighbourCache*);
template SmoothResult smooth<HexMesh>(HexMesh&, const IdVector<NodeId, char>&,
                                      const IdVector<NodeId, NodeConstraint>&,
                                      const SmoothOptions&, const std::vector<NodeId>*,
                                      const SizeCriterion&, NeighbourCache*);

}  // namespace hexadapt
