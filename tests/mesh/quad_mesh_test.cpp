#include "hexadapt/mesh/quad_mesh.h"

#include <gtest/gtest.h>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

TEST(QuadMesh, KeepsTheGivenNodeOrder) {
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const QuadMesh m(pts, {{NodeId(2), NodeId(3), NodeId(0), NodeId(1)}});
  const auto v = m.cell_nodes(CellId(0));
  EXPECT_EQ(v[0], NodeId(2));
  EXPECT_EQ(v[1], NodeId(3));
  EXPECT_EQ(v[2], NodeId(0));
  EXPECT_EQ(v[3], NodeId(1));
  EXPECT_EQ(m.face_nodes(CellId(0), 1)[0], NodeId(3));
}

TEST(QuadMesh, NeighboursOfAGrid) {
  const QuadMesh m = make_quad_grid(3, 3);
  const CellId centre(4);
  EXPECT_EQ(m.neighbour(centre, 0), CellId(1));  // below, across edge 0-1
  EXPECT_EQ(m.neighbour(centre, 1), CellId(5));  // right
  EXPECT_EQ(m.neighbour(centre, 2), CellId(7));  // above
  EXPECT_EQ(m.neighbour(centre, 3), CellId(3));  // left
  EXPECT_FALSE(m.neighbour(CellId(0), 0).valid());
  EXPECT_FALSE(m.neighbour(CellId(0), 3).valid());
  EXPECT_EQ(m.node_cells(NodeId(5)).size(), 4u);
}

TEST(QuadMesh, AreaAndQualitySigned) {
  const QuadMesh m = make_quad_grid(std::vector<double>{0, 2}, std::vector<double>{0, 3});
  EXPECT_NEAR(m.cell_volume(CellId(0)), 6.0, 1e-14);
  EXPECT_NEAR(m.cell_quality(CellId(0)), 1.0, 1e-15);
}

TEST(QuadMesh, RejectsNonManifoldAndMisorientedEdges) {
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {1, -1, 0}, {0, -1, 0}, {2, 0, 0}, {2, 1, 0}};
  using C = QuadMesh::CellNodes;
  // Same direction for the shared edge 1-2: inconsistent orientation.
  EXPECT_THROW(QuadMesh(pts, {C{NodeId(0), NodeId(1), NodeId(2), NodeId(3)},
                              C{NodeId(1), NodeId(2), NodeId(7), NodeId(6)}}),
               MeshError);
  // Edge 0-1 used by three cells.
  EXPECT_THROW(QuadMesh(pts, {C{NodeId(0), NodeId(1), NodeId(2), NodeId(3)},
                              C{NodeId(5), NodeId(4), NodeId(1), NodeId(0)},
                              C{NodeId(1), NodeId(0), NodeId(3), NodeId(7)}}),
               MeshError);
}

}  // namespace
}  // namespace hexadapt
