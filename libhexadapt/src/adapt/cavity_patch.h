// The mesh that cavity pillowing (paper sec. 5.2) edits, and the local patches a cavity is
// tried in, so that a cavity attempt costs time in the size of the cavity, not of the mesh.
// Internal to the library.
//
// EditableMesh holds the cells, points and node -> cells lists as plain arrays that a
// published cavity is spliced into; the kernel (QuadMesh, HexMesh) is built once at the end.
// A patch is the cavity's cells plus every cell sharing a node with them, with local ids
// increasing with the global ones. Every node of the cavity then has its whole star in the
// patch, so the patch's boundary faces at those nodes are domain-boundary faces, and
// pillowing, boundary constraints, smoothing and quality of the cavity's nodes and cells
// come out exactly as in the whole mesh (same faces, same fans, same order of new nodes and
// cells, same colouring of the smoothed nodes).
#pragma once

#include <vector>

#include "hexadapt/adapt/pillow.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::detail {

/// A cavity's cells and the ring around them, with local ids.
template <class M>
struct CavityPatch {
  M mesh;
  std::vector<CellId> cells;      ///< global id of each local cell, increasing
  std::vector<NodeId> nodes;      ///< global id of each local node, increasing
  IdVector<CellId, char> in_set;  ///< local cells of the cavity
};

template <class M>
class EditableMesh {
 public:
  explicit EditableMesh(const M& mesh);

  index_t n_cells() const { return static_cast<index_t>(cells_.size()); }
  index_t n_nodes() const { return static_cast<index_t>(points_.size()); }
  const typename M::CellNodes& cell_nodes(CellId c) const { return cells_[c.idx()]; }
  /// Cells around n, increasing.
  const std::vector<CellId>& node_cells(NodeId n) const { return node_cells_[n.idx()]; }

  /// The patch of `set` (global cell ids, increasing); the whole mesh when `whole`.
  CavityPatch<M> patch(const std::vector<CellId>& set, bool whole) const;
  /// Publishes the pillowed patch: moved points, the cavity cells' new nodes, the new nodes
  /// and layer cells appended in the pillowing's order. Returns the global id of each node
  /// of p.mesh.
  std::vector<NodeId> splice(const CavityPatch<M>& patch, const PillowResult<M>& p);
  /// The kernel of the current cells and points.
  M build() const;

 private:
  std::vector<Vec3> points_;
  std::vector<typename M::CellNodes> cells_;
  std::vector<std::vector<CellId>> node_cells_;
};

}  // namespace hexadapt::detail
