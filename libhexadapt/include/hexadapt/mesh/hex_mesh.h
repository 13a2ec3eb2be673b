// HexMesh: the compact half-face kernel for all-hex meshes (DESIGN sec. 3).
//
// A cell is 8 node ids in binary lattice order (see ref_hex in geometry.h). Half-face
// h = 6 * c + lf names local face lf of cell c; opposite(h) is the half-face of the
// neighbouring cell glued to it, invalid on the boundary. Node -> cells adjacency is built on
// demand. Topology is immutable: edits (pillowing) build a new mesh plus old -> new maps.
// Geometry is one positions array beside the topology and may be changed freely.
#pragma once

#include <array>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/node_cells.h"

namespace hexadapt {

class HexMesh {
 public:
  static constexpr int dim = 3;
  static constexpr int nodes_per_cell = 8;
  static constexpr int faces_per_cell = 6;
  static constexpr int nodes_per_face = 4;
  using CellNodes = std::array<NodeId, 8>;
  using FaceNodes = std::array<NodeId, 4>;

  HexMesh() = default;
  /// Builds the kernel. Throws MeshError when a cell refers to a missing node, repeats a node,
  /// or a face is shared by more than two cells.
  HexMesh(std::vector<Vec3> points, std::vector<CellNodes> cells);

  index_t n_cells() const { return static_cast<index_t>(cells_.size()); }
  index_t n_nodes() const { return static_cast<index_t>(points_.size()); }

  const CellNodes& cell_nodes(CellId c) const { return cells_[c.idx()]; }
  FaceNodes face_nodes(CellId c, int lf) const;

  static HalfFaceId half_face(CellId c, int lf) { return HalfFaceId(6 * c.value() + lf); }
  static CellId cell_of(HalfFaceId h) { return CellId(h.value() / 6); }
  static int local_face(HalfFaceId h) { return h.value() % 6; }
  HalfFaceId opposite(HalfFaceId h) const { return opposite_[h.idx()]; }
  bool is_boundary(HalfFaceId h) const { return !opposite_[h.idx()].valid(); }
  /// The cell across local face lf of c, invalid on the boundary.
  CellId neighbour(CellId c, int lf) const {
    const HalfFaceId o = opposite(half_face(c, lf));
    return o.valid() ? cell_of(o) : CellId::invalid();
  }
  /// Every half-face with no opposite, in increasing order.
  std::vector<HalfFaceId> boundary_half_faces() const;

  /// Cells around node n, in increasing cell id.
  Span<CellId> node_cells(NodeId n) const;

  const Vec3& point(NodeId n) const { return points_[n.idx()]; }
  void set_point(NodeId n, const Vec3& p) { points_[n.idx()] = p; }
  const std::vector<Vec3>& points() const { return points_; }
  std::array<Vec3, 8> cell_points(CellId c) const;

  /// Exact volume of the trilinear hex (2x2x2 Gauss quadrature of det J); negative if inverted.
  double cell_volume(CellId c) const;
  /// Scaled Jacobian (Verdict definition), in [-1, 1].
  double cell_quality(CellId c) const;

 private:
  std::vector<Vec3> points_;
  std::vector<CellNodes> cells_;
  std::vector<HalfFaceId> opposite_;
  LazyNodeCells node_cells_;
};

}  // namespace hexadapt
