#include "hexadapt/mesh/hex_mesh.h"

#include <gtest/gtest.h>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

TEST(HexMesh, GridOppositesAreSymmetricAndBoundaryIsTheBox) {
  const HexMesh m = make_hex_grid(3, 2, 4);
  ASSERT_EQ(m.n_cells(), 24);
  ASSERT_EQ(m.n_nodes(), 4 * 3 * 5);
  for (CellId c : id_range<CellId>(m.n_cells()))
    for (int lf = 0; lf < 6; ++lf) {
      const HalfFaceId h = HexMesh::half_face(c, lf), o = m.opposite(h);
      if (!o.valid()) continue;
      EXPECT_EQ(m.opposite(o), h);
      EXPECT_EQ(HexMesh::local_face(o), lf ^ 1);  // grids glue x+ to x-, and so on
    }
  // boundary faces of a 3x2x4 box: 2*(3*2 + 3*4 + 2*4)
  EXPECT_EQ(m.boundary_half_faces().size(), 52u);
}

TEST(HexMesh, NeighboursFollowTheLatticeNumbering) {
  const HexMesh m = make_hex_grid(3, 3, 3);
  const CellId centre(13);  // (1,1,1)
  EXPECT_EQ(m.neighbour(centre, 0), CellId(12));
  EXPECT_EQ(m.neighbour(centre, 1), CellId(14));
  EXPECT_EQ(m.neighbour(centre, 2), CellId(10));
  EXPECT_EQ(m.neighbour(centre, 3), CellId(16));
  EXPECT_EQ(m.neighbour(centre, 4), CellId(4));
  EXPECT_EQ(m.neighbour(centre, 5), CellId(22));
  EXPECT_FALSE(m.neighbour(CellId(0), 0).valid());
}

TEST(HexMesh, NodeCellsAreSortedAndComplete) {
  const HexMesh m = make_hex_grid(2, 2, 2);
  const auto around = m.node_cells(NodeId(13));  // the centre node
  ASSERT_EQ(around.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(around[i], CellId(i));
  EXPECT_EQ(m.node_cells(NodeId(0)).size(), 1u);
}

TEST(HexMesh, FacesPointOutwards) {
  const HexMesh m = make_hex_grid(1, 1, 1);
  const Vec3 centre(0.5, 0.5, 0.5);
  for (int lf = 0; lf < 6; ++lf) {
    const auto f = m.face_nodes(CellId(0), lf);
    const Vec3 a = m.point(f[0]), b = m.point(f[1]), c = m.point(f[2]);
    const Vec3 normal = (b - a).cross(c - b);
    EXPECT_GT(normal.dot(a - centre), 0) << "face " << lf;
  }
}

TEST(HexMesh, VolumeAndQualityOfAUnitCell) {
  const HexMesh m = make_hex_grid(1, 1, 1, Vec3(1, 2, 3), Vec3(2, 3, 4));
  EXPECT_NEAR(m.cell_volume(CellId(0)), 24.0, 1e-12);
  EXPECT_NEAR(m.cell_quality(CellId(0)), 1.0, 1e-15);
}

TEST(HexMesh, RejectsNonManifoldFacesAndBadIds) {
  // Three cells on one face: two copies of the upper cell of a 1x1x2 column.
  HexMesh grid = make_hex_grid(1, 1, 2);
  std::vector<HexMesh::CellNodes> cells = {grid.cell_nodes(CellId(0)), grid.cell_nodes(CellId(1))};
  auto third = cells[1];
  std::vector<Vec3> pts = grid.points();
  for (int v = 4; v < 8; ++v) {
    pts.push_back(pts[third[static_cast<std::size_t>(v)].idx()] + Vec3(0, 0, 5));
    third[static_cast<std::size_t>(v)] = NodeId(static_cast<index_t>(pts.size() - 1));
  }
  cells.push_back(third);
  EXPECT_THROW(HexMesh(pts, cells), MeshError);
  auto bad = cells[0];
  bad[3] = NodeId(999);
  EXPECT_THROW(HexMesh(grid.points(), {bad}), MeshError);
  bad = cells[0];
  bad[3] = bad[2];
  EXPECT_THROW(HexMesh(grid.points(), {bad}), MeshError);
}

}  // namespace
}  // namespace hexadapt
