// QuadMesh: all-quad 2D meshes on OpenMesh's array kernel, double precision.
//
// Cells are OpenMesh faces, nodes OpenMesh vertices, with identical indices (cell c is face
// c, node n is vertex n). Cells are counter-clockwise in the xy plane; the interface mirrors
// HexMesh's so that algorithms are written once for both (cell_complex.h). Local face lf of
// a quad is its edge from node lf to node (lf + 1) % 4. Topology is immutable after
// construction; point positions may change. The OpenMesh mesh is available for algorithms
// that need its circulators and properties.
#pragma once

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <array>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/node_cells.h"

namespace hexadapt {

using OmPolyMesh = OpenMesh::PolyMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;

class QuadMesh {
 public:
  static constexpr int dim = 2;
  static constexpr int nodes_per_cell = 4;
  static constexpr int faces_per_cell = 4;
  static constexpr int nodes_per_face = 2;
  using CellNodes = std::array<NodeId, 4>;
  using FaceNodes = std::array<NodeId, 2>;

  QuadMesh() = default;
  /// Builds the mesh from counter-clockwise quads. Throws MeshError when a cell refers to a
  /// missing node, repeats a node, an edge is shared by more than two cells, or two cells
  /// sharing an edge list it in the same direction (inconsistent orientation).
  QuadMesh(std::vector<Vec3> points, std::vector<CellNodes> cells);

  index_t n_cells() const { return static_cast<index_t>(om_.n_faces()); }
  index_t n_nodes() const { return static_cast<index_t>(om_.n_vertices()); }

  CellNodes cell_nodes(CellId c) const;
  FaceNodes face_nodes(CellId c, int lf) const;
  /// The cell across edge lf of c, invalid on the boundary.
  CellId neighbour(CellId c, int lf) const;
  /// Cells around node n, in increasing cell id.
  Span<CellId> node_cells(NodeId n) const;

  Vec3 point(NodeId n) const;
  void set_point(NodeId n, const Vec3& p);
  std::array<Vec3, 4> cell_points(CellId c) const;

  /// Signed area (positive for counter-clockwise cells).
  double cell_volume(CellId c) const;
  /// Signed scaled Jacobian with the +z orientation, in [-1, 1].
  double cell_quality(CellId c) const;

  const OmPolyMesh& openmesh() const { return om_; }

 private:
  OmPolyMesh::HalfedgeHandle edge_halfedge(CellId c, int lf) const;

  OmPolyMesh om_;
  LazyNodeCells node_cells_;
};

}  // namespace hexadapt
