// LocalBall: the cells around one node and their local topology, the unit on which the
// manifold test (manifold.h) and the configuration enumeration (enumerate.h) work (paper
// sec. 3.2, the set B_n of Algorithm 2).
//
// The ball's cells are numbered 0..k-1 in a geometric order (centroid, lexicographic on
// x, y, z; cell id only for coincident centroids), so every choice made on a ball (ties
// between configurations) follows the geometry rather than the order cells are stored in.
// For each cell and local face the ball keeps the local index of the neighbour across that
// face when the neighbour is in the ball (-1 otherwise), and the face's nodes and, in 3D, its
// edges renumbered into small local ids, so that counting the vertices, edges and faces of a
// union of cells is a few bit operations.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hexadapt/core/ids.h"

namespace hexadapt::assign {

template <class M>
class LocalBall {
 public:
  static constexpr int max_cells = 64;    ///< a node with more cells is rejected (MeshError)
  static constexpr int max_local = 1024;  ///< bound on local node and edge ids

  struct Face {
    int neighbour = -1;                                    ///< local cell across, -1 if none
    std::array<std::uint16_t, M::nodes_per_face> nodes{};  ///< local node ids
    std::array<std::uint16_t, M::nodes_per_face> edges{};  ///< local edge ids (3D only)
  };

  /// Gathers node n's cells. Throws MeshError when n has more than max_cells cells.
  LocalBall(const M& mesh, NodeId n);

  NodeId node() const { return node_; }
  int n_cells() const { return static_cast<int>(cells_.size()); }
  CellId cell(int i) const { return cells_[static_cast<std::size_t>(i)]; }
  const std::vector<CellId>& cells() const { return cells_; }
  const Face& face(int i, int lf) const {
    return faces_[static_cast<std::size_t>(i)][static_cast<std::size_t>(lf)];
  }
  int n_local_nodes() const { return n_nodes_; }
  int n_local_edges() const { return n_edges_; }

  /// 3D: the cells around one edge through the node, and who is next to whom around it
  /// (through the faces holding the edge). Empty in 2D.
  struct Fan {
    std::uint64_t cells = 0;             ///< bit i: ball cell i holds the edge
    std::vector<std::uint64_t> next_to;  ///< per ball cell: its neighbours in the fan
  };
  const std::vector<Fan>& fans() const { return fans_; }

 private:
  void build_fans(int centre);

  NodeId node_;
  std::vector<CellId> cells_;
  std::vector<std::array<Face, M::faces_per_cell>> faces_;
  int n_nodes_ = 0;
  int n_edges_ = 0;
  std::vector<Fan> fans_;
};

}  // namespace hexadapt::assign
