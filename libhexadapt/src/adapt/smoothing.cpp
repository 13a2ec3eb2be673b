#include "hexadapt/adapt/smoothing.h"

#include <string>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {

namespace {

// One node: the largest halving of the Laplacian displacement that does not lower the local
// minimum quality. Returns the gain in local minimum (0 when the node did not move).
template <class M>
double smooth_node(M& mesh, NodeId n, const NodeConstraint& constraint, int halvings) {
  const std::vector<NodeId> around = edge_neighbours(mesh, n);
  if (around.empty()) return 0;
  Vec3 mean = Vec3::Zero();
  for (NodeId o : around) mean += mesh.point(o);
  mean /= static_cast<double>(around.size());
  const Vec3 p = mesh.point(n);
  Vec3 d = constraint.project(mean - p);
  if (!(d.norm() > 0)) return 0;
  const double before = min_quality_around(mesh, n);
  for (int h = 0; h <= halvings; ++h, d *= 0.5) {
    mesh.set_point(n, p + d);
    const double after = min_quality_around(mesh, n);
    if (after >= before) return after - before;
  }
  mesh.set_point(n, p);
  return -1;
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
        gain[static_cast<std::size_t>(i)] = smooth_node(mesh, n, constraint[n], options.halvings);
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
