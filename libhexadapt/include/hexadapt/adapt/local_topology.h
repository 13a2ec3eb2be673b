// Navigation around a node that the adaptation steps share (paper sec. 5): the corner of a
// cell a node is, the nodes joined to it by a cell edge and their mean distance, the outward
// normal of a cell face, and a conflict-free colouring of nodes for parallel moves.
//
// The only dimensional facts live here: a quad corner's edge neighbours are the previous and
// next corners, a hex corner's (binary numbering) are the corners one bit away.
#pragma once

#include <array>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt {

/// The corners joined to corner `local` by an edge of the reference cell.
template <class M>
constexpr std::array<int, M::dim> corner_edge_neighbours(int local) {
  if constexpr (M::dim == 2) {
    return {(local + 1) % 4, (local + 3) % 4};
  } else {
    return {local ^ 1, local ^ 2, local ^ 4};
  }
}

/// Position of n among the corners of c, -1 when c does not hold n.
template <class M>
int corner_of(const M& mesh, CellId c, NodeId n) {
  const auto nodes = mesh.cell_nodes(c);
  for (int k = 0; k < M::nodes_per_cell; ++k)
    if (nodes[static_cast<std::size_t>(k)] == n) return k;
  return -1;
}

/// Nodes sharing a cell edge with n, increasing ids, without repeats.
template <class M>
std::vector<NodeId> edge_neighbours(const M& mesh, NodeId n);

/// edge_neighbours of the nodes asked for, each computed once: for the smoothing, which asks
/// for a node's neighbours at every try, again and again on one topology. Different threads
/// may ask for different nodes at the same time.
class NeighbourCache {
 public:
  explicit NeighbourCache(index_t n_nodes)
      : lists_(static_cast<std::size_t>(n_nodes)), known_(static_cast<std::size_t>(n_nodes), 0) {}
  index_t n_nodes() const { return static_cast<index_t>(lists_.size()); }
  template <class M>
  const std::vector<NodeId>& of(const M& mesh, NodeId n) {
    if (!known_[n]) {
      lists_[n] = edge_neighbours(mesh, n);
      lists_[n].shrink_to_fit();  // a list is built with room for every corner's neighbours
      known_[n] = 1;
    }
    return lists_[n];
  }

 private:
  IdVector<NodeId, std::vector<NodeId>> lists_;
  IdVector<NodeId, char> known_;
};

/// Mean distance from n to `around` (its edge_neighbours, not empty): the node's length scale.
template <class M>
double mean_edge_length(const M& mesh, NodeId n, const std::vector<NodeId>& around) {
  double len = 0;
  for (NodeId o : around) len += (mesh.point(o) - mesh.point(n)).norm();
  return len / static_cast<double>(around.size());
}

/// Unit normal of local face lf of c, pointing out of c (2D: in the xy plane).
template <class M>
Vec3 face_normal(const M& mesh, CellId c, int lf);

/// Splits `nodes` into classes in which no two nodes share a cell, so that moving the nodes
/// of one class in parallel never reads a point another thread writes. Greedy colouring in
/// the order given: the classes depend on the input only, never on the thread count.
template <class M>
std::vector<std::vector<NodeId>> independent_node_sets(const M& mesh,
                                                       const std::vector<NodeId>& nodes);

/// f(i) for i in [0, n): on the library's threads when n is large enough to pay for waking
/// them (a small colour class costs more to share than to run), in order otherwise. f must
/// only write state owned by item i, so the result is the same either way.
template <class F>
void for_each_item(std::size_t n, F&& f) {
  constexpr std::size_t min_parallel = 256;
  if (n < min_parallel) {
    for (std::size_t i = 0; i < n; ++i) f(static_cast<std::int64_t>(i));
  } else {
    parallel_for(static_cast<std::int64_t>(n), f);
  }
}

}  // namespace hexadapt
