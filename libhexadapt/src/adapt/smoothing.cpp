#include "hexadapt/adapt/smoothing.h"

#include <string>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {

namespace {

// One node: the largest halving of the Laplacian displacement that does not lower the local
// minimum quality. Returns the gain in local minimum (0 when the node did not move). `q`: the
// local minimum, on entry and on return (each evaluation costs the cells around the node).
template <class M>
double laplacian_step(M& mesh, NodeId n, const std::vector<NodeId>& around,
                      const NodeConstraint& constraint, int halvings, double& q) {
  Vec3 mean = Vec3::Zero();
  for (NodeId o : around) mean += mesh.point(o);
  mean /= static_cast<double>(around.size());
  const Vec3 p = mesh.point(n);
  Vec3 d = constraint.project(mean - p);
  if (!(d.norm() > 0)) return 0;
  const double before = q;
  for (int h = 0; h <= halvings; ++h, d *= 0.5) {
    mesh.set_point(n, p + d);
    const double after = min_quality_around(mesh, n);
    if (after >= before) {
      q = after;
      return after - before;
    }
  }
  mesh.set_point(n, p);
  return -1;
}

// Compass search on the local minimum quality: steps along +-x, +-y (+-z), projected on the
// constraint, keeping the best strict improvement, halving the step when none improves.
template <class M>
double pattern_search(M& mesh, NodeId n, const std::vector<NodeId>& around,
                      const NodeConstraint& constraint, int levels, double& q) {
  double len = 0;
  for (NodeId o : around) len += (mesh.point(o) - mesh.point(n)).norm();
  double h = 0.25 * len / static_cast<double>(around.size());
  const double start = q;
  double best = start;
  for (int level = 0; level < levels; ++level, h *= 0.5) {
    bool improved = true;
    while (improved) {
      improved = false;
      const Vec3 p = mesh.point(n);
      Vec3 best_p = p;
      for (int axis = 0; axis < M::dim; ++axis)
        for (double sign : {1.0, -1.0}) {
          const Vec3 d = constraint.project(sign * h * Vec3::Unit(axis));
          if (!(d.norm() > 1e-3 * h)) continue;
          mesh.set_point(n, p + d);
          const double trial = min_quality_around(mesh, n);
          if (trial > best + 1e-9) {
            best = trial;
            best_p = p + d;
            improved = true;
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
                   const SmoothOptions& options) {
  const std::vector<NodeId> around = edge_neighbours(mesh, n);
  if (around.empty()) return 0;
  double q = min_quality_around(mesh, n);
  double gain = laplacian_step(mesh, n, around, constraint, options.halvings, q);
  if (q < options.optimise_below) {
    const double more = pattern_search(mesh, n, around, constraint, options.search_levels, q);
    if (more > 0) gain = std::max(gain, 0.0) + more;
  }
  return gain;
}

}  // namespace

template <class M>
SmoothResult smooth(M& mesh, const IdVector<NodeId, char>& movable,
                    const IdVector<NodeId, NodeConstraint>& constraint,
                    const SmoothOptions& options) {
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  if (movable.size() != nn || constraint.size() != nn)
    throw InternalError("smoothing: movable flags or constraints do not match the mesh");
  if (options.iterations < 0 || options.halvings < 0)
    throw OptionError("smoothing iterations and halvings must be >= 0");
  std::vector<NodeId> nodes;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (movable[n] && !constraint[n].fixed(M::dim)) nodes.push_back(n);
  const auto sets = independent_node_sets(mesh, nodes);
  SmoothResult out;
  while (out.iterations < options.iterations) {
    ++out.iterations;
    double best_gain = 0;
    for (const auto& set : sets) {
      std::vector<double> gain(set.size(), -1);
      for_each_item(set.size(), [&](std::int64_t i) {
        const NodeId n = set[static_cast<std::size_t>(i)];
        gain[static_cast<std::size_t>(i)] = smooth_node(mesh, n, constraint[n], options);
      });
      for (double g : gain) {
        if (g >= 0) ++out.moves;
        best_gain = std::max(best_gain, g);
      }
    }
    if (best_gain <= options.min_gain) break;
  }
  return out;
}

template SmoothResult smooth<QuadMesh>(QuadMesh&, const IdVector<NodeId, char>&,
                                       const IdVector<NodeId, NodeConstraint>&,
                                       const SmoothOptions&);
template SmoothResult smooth<HexMesh>(HexMesh&, const IdVector<NodeId, char>&,
                                      const IdVector<NodeId, NodeConstraint>&,
                                      const SmoothOptions&);

}  // namespace hexadapt
