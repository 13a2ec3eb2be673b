#include "hexadapt/adapt/controlled_move.h"

#include <string>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {

namespace {

// Tries to put n at p; keeps it there when the cells around it stay acceptable.
template <class M>
bool try_position(M& mesh, NodeId n, const Vec3& p, double threshold, const SizeCriterion& size) {
  const Vec3 old = mesh.point(n);
  const double before = min_score_around(mesh, n, size);
  mesh.set_point(n, p);
  const double after = min_score_around(mesh, n, size);
  if (after >= threshold || after >= before) return true;
  mesh.set_point(n, old);
  return false;
}

}  // namespace

template <class M>
MoveResult controlled_move(M& mesh, const Targets& targets, const MoveOptions& options,
                           const SizeCriterion& size) {
  if (options.steps < 1)
    throw OptionError("steps must be at least 1, got " + std::to_string(options.steps));
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  MoveResult out;
  out.reached.assign(nn, 1);
  std::vector<NodeId> moving;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (targets.has[n] && mesh.point(n) != targets.position[n]) {
      moving.push_back(n);
      out.reached[n] = 0;
    }
  out.n_moving = static_cast<index_t>(moving.size());
  IdVector<NodeId, Vec3> start(nn);
  IdVector<NodeId, int> done(nn, 0);  // steps taken
  for (NodeId n : moving) start[n] = mesh.point(n);
  const auto sets = independent_node_sets(mesh, moving);
  const int max_rounds = options.max_rounds > 0 ? options.max_rounds : 4 * options.steps;
  const double inv_steps = 1.0 / options.steps;
  // A refused node waits until something around it moves before trying again.
  IdVector<NodeId, char> waiting(nn, 0);
  for (bool advanced = true; advanced && out.rounds < max_rounds; ++out.rounds) {
    advanced = false;
    for (const auto& set : sets) {
      std::vector<char> moved(set.size(), 0);
      for_each_item(set.size(), [&](std::int64_t i) {
        const NodeId n = set[static_cast<std::size_t>(i)];
        if (done[n] >= options.steps || waiting[n]) return;
        const int k = done[n] + 1;
        const Vec3 p = k == options.steps
                           ? targets.position[n]
                           : Vec3(start[n] + (k * inv_steps) * (targets.position[n] - start[n]));
        if (!try_position(mesh, n, p, options.threshold, size)) {
          waiting[n] = 1;
          return;
        }
        done[n] = k;
        moved[static_cast<std::size_t>(i)] = 1;
      });
      for (std::size_t i = 0; i < set.size(); ++i) {
        if (!moved[i]) continue;
        advanced = true;
        for (CellId c : mesh.node_cells(set[i]))
          for (NodeId o : mesh.cell_nodes(c)) waiting[o] = 0;
      }
    }
  }
  for (NodeId n : moving)
    if (done[n] >= options.steps) {
      out.reached[n] = 1;
      ++out.n_reached;
    }
  out.dist = target_distance(mesh, targets);
  return out;
}

template <class M>
MoveResult direct_move(M& mesh, const Targets& targets) {
  MoveResult out;
  out.reached.assign(static_cast<std::size_t>(mesh.n_nodes()), 1);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (targets.has[n] && mesh.point(n) != targets.position[n]) {
      mesh.set_point(n, targets.position[n]);
      ++out.n_moving;
    }
  out.n_reached = out.n_moving;
  out.rounds = 1;
  out.dist = target_distance(mesh, targets);
  return out;
}

#define HEXADAPT_INSTANTIATE(M)                                                   \
  template MoveResult controlled_move<M>(M&, const Targets&, const MoveOptions&, \
                                         const SizeCriterion&);                 \
  template MoveResult direct_move<M>(M&, const Targets&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
