#include "hexadapt/adapt/controlled_move.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {

namespace {

// Tries to put n at p; keeps it there when every cell around it stays acceptable: at or above
// the threshold, or, for a cell below it (a bad input, a layer cell the move may mend), no
// worse than it was.
template <class M>
bool try_position(M& mesh, NodeId n, const Vec3& p, double threshold, const SizeCriterion& size) {
  const Vec3 old = mesh.point(n);
  mesh.set_point(n, p);
  if (min_score_around(mesh, n, size, threshold) >= threshold) return true;
  mesh.set_point(n, old);
  std::vector<double> before;
  for (CellId c : mesh.node_cells(n)) before.push_back(cell_score(mesh, c, size));
  if (*std::min_element(before.begin(), before.end()) >= threshold) return false;
  mesh.set_point(n, p);
  std::size_t k = 0;
  for (CellId c : mesh.node_cells(n)) {
    const double s = cell_score(mesh, c, size);
    if (s < threshold && s < before[k]) {
      mesh.set_point(n, old);
      return false;
    }
    ++k;
  }
  return true;
}

// Puts n at p with its free edge neighbours moved by the same displacement (projected on
// their constraints): those ahead of it, or with `all` every one (a node of a pillowed
// interface then carries its layer copies on both sides along, and the layer cells keep
// their shape); keeps that when every cell around n and around them keeps the criteria, and
// returns the dragged nodes then (none: nothing moved).
template <class M>
std::vector<NodeId> try_drag(M& mesh, NodeId n, const Vec3& p, double threshold,
                             const SizeCriterion& size, const Targets& targets,
                             const IdVector<NodeId, NodeConstraint>& constraint, bool all) {
  const Vec3 old = mesh.point(n);
  const Vec3 d = p - old;
  std::vector<std::pair<NodeId, Vec3>> ahead;
  for (NodeId f : edge_neighbours(mesh, n))
    if (!targets.has[f] && !constraint[f].fixed(M::dim) &&
        (all || (mesh.point(f) - old).dot(d) > 0))
      ahead.emplace_back(f, mesh.point(f));
  if (ahead.empty()) return {};
  mesh.set_point(n, p);
  for (const auto& [f, at] : ahead) mesh.set_point(f, at + constraint[f].project(d));
  bool ok = min_score_around(mesh, n, size, threshold) >= threshold;
  for (std::size_t i = 0; ok && i < ahead.size(); ++i)
    ok = min_score_around(mesh, ahead[i].first, size, threshold) >= threshold;
  std::vector<NodeId> dragged;
  for (const auto& [f, at] : ahead) {
    if (ok)
      dragged.push_back(f);
    else
      mesh.set_point(f, at);
  }
  if (!ok) mesh.set_point(n, old);
  return dragged;
}

// An orthonormal basis of the displacements a constraint allows (2D meshes: in the xy plane).
template <int Dim>
std::vector<Vec3> tangent_basis(const NodeConstraint& c) {
  std::vector<Vec3> basis;
  for (int a = 0; a < Dim; ++a) {
    Vec3 d = c.project(Vec3::Unit(a));
    for (const Vec3& b : basis) d -= d.dot(b) * b;
    if (d.norm() > 1e-6) basis.push_back(d.normalized());
  }
  return basis;
}

// Unit directions in the span of the basis: both ways along a line; eight, 45 degrees apart,
// in a plane.
std::vector<Vec3> ring_directions(const std::vector<Vec3>& basis) {
  if (basis.size() == 1) return {basis[0], -basis[0]};
  std::vector<Vec3> out;
  const double s = std::sqrt(0.5);
  const std::array<Vec3, 4> half = {basis[0], Vec3(s * (basis[0] + basis[1])), basis[1],
                                    Vec3(s * (basis[1] - basis[0]))};
  for (const Vec3& d : half) out.insert(out.end(), {d, Vec3(-d)});
  return out;
}

// Puts n on the nearest ring of points of its surface around its target that holds a point
// where every cell around n keeps the criteria (the best such point of the ring). Returns
// false and leaves n where it was when no ring does.
template <class M>
bool slide(M& mesh, NodeId n, const Vec3& target, const NodeConstraint& surface, double threshold,
           const SizeCriterion& size) {
  const std::vector<Vec3> basis = tangent_basis<M::dim>(surface);
  if (basis.empty()) return false;
  const std::vector<NodeId> around = edge_neighbours(mesh, n);
  if (around.empty()) return false;
  const Vec3 old = mesh.point(n);
  // The radii's unit: the local size of n's cells, or its mean edge length without sizes.
  const double h =
      size.local_size.empty() ? mean_edge_length(mesh, n, around) : node_local_size(mesh, n, size);
  const std::vector<Vec3> directions = ring_directions(basis);
  for (double r : {0.0625, 0.125, 0.25, 0.375, 0.5}) {
    double best = threshold;
    Vec3 best_p = old;
    bool found = false;
    for (const Vec3& d : directions) {
      const Vec3 p = target + r * h * d;
      mesh.set_point(n, p);
      const double s = min_score_around(mesh, n, size, best);
      if (s >= best && (!found || s > best)) {
        best = s;
        best_p = p;
        found = true;
      }
    }
    mesh.set_point(n, best_p);
    if (found) return true;
  }
  return false;
}

// Every node left short of its target tries to slide onto its surface; nodes sharing no cell
// in parallel, in a fixed order.
template <class M>
void slide_blocked(M& mesh, const Targets& targets, const IdVector<NodeId, NodeConstraint>& surface,
                   double threshold, const SizeCriterion& size, MoveResult& out) {
  std::vector<NodeId> blocked;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (!out.on_surface[n]) blocked.push_back(n);
  for (const auto& set : independent_node_sets(mesh, blocked)) {
    std::vector<char> slid(set.size(), 0);
    for_each_item(set.size(), [&](std::int64_t i) {
      const NodeId n = set[static_cast<std::size_t>(i)];
      slid[static_cast<std::size_t>(i)] =
          slide(mesh, n, targets.position[n], surface[n], threshold, size);
    });
    for (std::size_t i = 0; i < set.size(); ++i)
      if (slid[i]) {
        out.on_surface[set[i]] = 1;
        ++out.n_slid;
      }
  }
}

}  // namespace

template <class M>
MoveResult controlled_move(M& mesh, const Targets& targets, const MoveOptions& options,
                           const StepSettings& shared, const SizeCriterion& size,
                           const IdVector<NodeId, NodeConstraint>* surface) {
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
  auto step_target = [&](NodeId n) {
    const int k = done[n] + 1;
    return k == options.steps ? targets.position[n]
                              : Vec3(start[n] + (k * inv_steps) * (targets.position[n] - start[n]));
  };
  auto wake_around = [&](NodeId v) {
    for (CellId c : mesh.node_cells(v))
      for (NodeId o : mesh.cell_nodes(c)) waiting[o] = 0;
  };
  for (bool advanced = true; advanced && out.rounds < max_rounds; ++out.rounds) {
    advanced = false;
    for (const auto& set : sets) {
      std::vector<char> moved(set.size(), 0), refused(set.size(), 0);
      for_each_item(set.size(), [&](std::int64_t i) {
        const NodeId n = set[static_cast<std::size_t>(i)];
        if (done[n] >= options.steps || waiting[n]) return;
        if (try_position(mesh, n, step_target(n), shared.threshold, size))
          moved[static_cast<std::size_t>(i)] = 1;
        else
          refused[static_cast<std::size_t>(i)] = 1;
      });
      // Drags move nodes that other members of the set share cells with: one at a time.
      std::vector<NodeId> dragged;
      for (std::size_t i = 0; options.drag && surface && i < set.size(); ++i) {
        if (!refused[i]) continue;
        std::vector<NodeId> d;
        for (bool all : {false, true})
          if (d.empty())
            d = try_drag(mesh, set[i], step_target(set[i]), shared.threshold, size, targets,
                         *surface, all);
        if (d.empty()) continue;
        moved[i] = 1;
        refused[i] = 0;
        ++out.n_drags;
        dragged.insert(dragged.end(), d.begin(), d.end());
      }
      for (std::size_t i = 0; i < set.size(); ++i) {
        if (refused[i]) waiting[set[i]] = 1;
        if (!moved[i]) continue;
        ++done[set[i]];
        advanced = true;
        wake_around(set[i]);
      }
      for (NodeId f : dragged) wake_around(f);
    }
  }
  for (NodeId n : moving)
    if (done[n] >= options.steps) {
      out.reached[n] = 1;
      ++out.n_reached;
    }
  out.on_surface = out.reached;
  if (surface) slide_blocked(mesh, targets, *surface, shared.threshold, size, out);
  out.dist = target_distance(mesh, targets);
  return out;
}

template <class M>
MoveResult direct_move(M& mesh, const Targets& targets) {
  MoveResult out;
  out.reached.assign(static_cast<std::size_t>(mesh.n_nodes()), 1);
  out.on_surface = out.reached;
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

#define HEXADAPT_INSTANTIATE(M)                                                     \
  template MoveResult controlled_move<M>(M&, const Targets&, const MoveOptions&,    \
                                         const StepSettings&, const SizeCriterion&, \
                                         const IdVector<NodeId, NodeConstraint>*);  \
  template MoveResult direct_move<M>(M&, const Targets&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
