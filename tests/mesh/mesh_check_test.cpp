// The mesh check on hand-built meshes with one known defect each, in 2D and in 3D.
#include "hexadapt/mesh/mesh_check.h"

#include <gtest/gtest.h>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

using Q = QuadMesh::CellNodes;
using H = HexMesh::CellNodes;

Q q(int a, int b, int c, int d) {
  return {NodeId(a), NodeId(b), NodeId(c), NodeId(d)};
}

// The cells of mesh m without the listed ones.
HexMesh without(const HexMesh& m, std::vector<int> drop) {
  std::vector<H> cells;
  for (CellId c : id_range<CellId>(m.n_cells()))
    if (std::find(drop.begin(), drop.end(), c.value()) == drop.end())
      cells.push_back(m.cell_nodes(c));
  return HexMesh(m.points(), cells);
}

TEST(MeshCheck, GridsAreClean) {
  const auto r2 = check_mesh(make_quad_grid(4, 3));
  EXPECT_TRUE(r2.ok());
  EXPECT_EQ(r2.boundary_faces, 14);
  const auto r3 = check_mesh(make_hex_grid(3, 2, 2, Vec3(1, 2, 3), Vec3(0.1, 2, 30)));
  EXPECT_TRUE(r3.ok());
  EXPECT_EQ(r3.boundary_faces, 2 * (6 + 6 + 4));
}

TEST(MeshCheck, UnreferencedNodes) {
  const QuadMesh grid = make_quad_grid(2, 2);
  std::vector<Vec3> pts;
  std::vector<Q> cells;
  for (NodeId n : id_range<NodeId>(grid.n_nodes())) pts.push_back(grid.point(n));
  for (CellId c : id_range<CellId>(grid.n_cells())) cells.push_back(grid.cell_nodes(c));
  pts.emplace_back(5, 5, 0);
  const auto r = check_mesh(QuadMesh(pts, cells));
  EXPECT_EQ(r.unreferenced_nodes, 1);
  ASSERT_EQ(r.first_unreferenced.size(), 1u);
  EXPECT_EQ(r.first_unreferenced[0].node, NodeId(9));
  EXPECT_FALSE(r.ok());
}

TEST(MeshCheck, DuplicateNodesOfACrack) {
  // Two unit quads side by side; the right one has its own copies of the shared nodes.
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1 + 1e-14, 0}};
  const auto r = check_mesh(QuadMesh(pts, {q(0, 1, 2, 3), q(4, 5, 6, 7)}));
  EXPECT_EQ(r.duplicate_nodes, 2);
  ASSERT_EQ(r.first_duplicates.size(), 2u);
  EXPECT_EQ(r.first_duplicates[0].node, NodeId(4));
  EXPECT_EQ(r.first_duplicates[0].other, NodeId(1));
  EXPECT_EQ(r.first_duplicates[1].node, NodeId(7));
  EXPECT_EQ(r.first_duplicates[1].other, NodeId(2));
  EXPECT_EQ(r.hanging_nodes, 0);  // at a corner's place: a duplicate, not a hanging node
  // Farther apart than the tolerance: not duplicates.
  MeshCheckOptions strict;
  strict.duplicate_tolerance = 1e-16;
  EXPECT_EQ(check_mesh(QuadMesh(pts, {q(0, 1, 2, 3), q(4, 5, 6, 7)}), strict).duplicate_nodes, 1);
}

TEST(MeshCheck, HangingNodeIn2D) {
  // A 1 x 2 cell on the left, two unit cells on the right: node 4 = (1, 1) hangs on the
  // right edge of the big cell, and nodes 1 and 2 are pinched (their stars touch at a node).
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0},
                                 {1, 1, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}};
  const auto r = check_mesh(QuadMesh(pts, {q(0, 1, 2, 3), q(1, 5, 6, 4), q(4, 6, 7, 2)}));
  EXPECT_EQ(r.hanging_nodes, 1);
  EXPECT_EQ(r.nonconformal_faces, 1);
  ASSERT_EQ(r.first_hanging.size(), 1u);
  EXPECT_EQ(r.first_hanging[0].node, NodeId(4));
  EXPECT_EQ(r.first_hanging[0].cell, CellId(0));
  EXPECT_EQ(r.first_hanging[0].local_face, 1);
  EXPECT_EQ(r.nonmanifold_nodes, 2);
  EXPECT_EQ(r.duplicate_nodes, 0);
  EXPECT_EQ(r.inverted_cells, 0);
}

TEST(MeshCheck, HangingNodesIn3D) {
  // One 2 x 2 x 1 hex under four unit hexes: the big top face holds 4 edge midpoints and its
  // centre, none of them its nodes.
  const HexMesh top = make_hex_grid(2, 2, 1, Vec3(0, 0, 1));
  std::vector<Vec3> pts = top.points();
  std::vector<H> cells;
  for (CellId c : id_range<CellId>(top.n_cells())) cells.push_back(top.cell_nodes(c));
  const auto base = static_cast<int>(pts.size());
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(2, 2, 0)}) pts.push_back(p);
  cells.push_back({NodeId(base), NodeId(base + 1), NodeId(base + 2), NodeId(base + 3), NodeId(0),
                   NodeId(2), NodeId(6), NodeId(8)});
  // Bend the big face a little: hanging nodes on a non-planar face are still found.
  pts[4].z() += 0.01;
  MeshCheckOptions all;
  all.max_listed = 100;
  const auto r = check_mesh(HexMesh(pts, cells), all);
  EXPECT_EQ(r.hanging_nodes, 4);  // the centre moved off the (bilinear) face: not on it
  // The edge midpoints also lie on the sides of the big cell's four side faces.
  EXPECT_EQ(r.nonconformal_faces, 5);
  ASSERT_EQ(r.first_hanging.size(), 4u);
  EXPECT_EQ(r.first_hanging[0].node, NodeId(1));
  EXPECT_EQ(r.first_hanging[0].cell, CellId(4));
  EXPECT_EQ(r.first_hanging[0].local_face, 2);  // y-, the first boundary face holding (1,0,1)
  EXPECT_EQ(r.first_hanging[1].node, NodeId(3));
  EXPECT_EQ(r.nonmanifold_nodes, 4);  // the big face's corners touch the small cells only there
  pts[4].z() -= 0.01;
  EXPECT_EQ(check_mesh(HexMesh(pts, cells)).hanging_nodes, 5);
}

TEST(MeshCheck, HangingNodeOnACurvedFace) {
  // A twisted (non-planar) big face: its bilinear midpoint still counts as on the face.
  const HexMesh top = make_hex_grid(2, 2, 1, Vec3(0, 0, 1));
  std::vector<Vec3> pts = top.points();
  for (int n : {8, 17}) pts[static_cast<std::size_t>(n)].z() += 0.3;  // corner (2,2) up
  pts[5].z() += 0.15;   // (2,1): midpoint of the raised side
  pts[7].z() += 0.15;   // (1,2)
  pts[4].z() += 0.075;  // centre: the bilinear value at (1/2, 1/2)
  std::vector<H> cells;
  for (CellId c : id_range<CellId>(top.n_cells())) cells.push_back(top.cell_nodes(c));
  const auto base = static_cast<int>(pts.size());
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(2, 2, 0)}) pts.push_back(p);
  cells.push_back({NodeId(base), NodeId(base + 1), NodeId(base + 2), NodeId(base + 3), NodeId(0),
                   NodeId(2), NodeId(6), NodeId(8)});
  EXPECT_EQ(check_mesh(HexMesh(pts, cells)).hanging_nodes, 5);
}

TEST(MeshCheck, InvertedAndDegenerateCells) {
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}};
  const auto r = check_mesh(QuadMesh(pts, {q(0, 3, 2, 1)}));  // clockwise
  EXPECT_EQ(r.inverted_cells, 1);
  ASSERT_EQ(r.first_inverted.size(), 1u);
  EXPECT_EQ(r.first_inverted[0].quality, -1.0);
  EXPECT_TRUE(r.first_inverted[0].centroid.isApprox(Vec3(0.5, 0.5, 0)));

  HexMesh cube = make_hex_grid(1, 1, 1);
  std::vector<Vec3> flat = cube.points();
  for (Vec3& p : flat) p.z() = 0;  // a flat hex: degenerate
  EXPECT_EQ(check_mesh(HexMesh(flat, {cube.cell_nodes(CellId(0))})).inverted_cells, 1);
}

TEST(MeshCheck, BowTieNodes) {
  // 2D: two quads touching at one node.
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  const auto r2 = check_mesh(QuadMesh(pts, {q(0, 1, 2, 3), q(2, 4, 5, 6)}));
  EXPECT_EQ(r2.nonmanifold_nodes, 1);
  EXPECT_EQ(r2.first_nonmanifold.at(0).node, NodeId(2));
  EXPECT_EQ(r2.hanging_nodes + r2.duplicate_nodes + r2.inverted_cells, 0);
  // The 2 x 2 grid without two diagonal cells.
  const QuadMesh grid = make_quad_grid(2, 2);
  std::vector<Vec3> gp;
  for (NodeId n : id_range<NodeId>(grid.n_nodes())) gp.push_back(grid.point(n));
  const auto r2b =
      check_mesh(QuadMesh(gp, {grid.cell_nodes(CellId(1)), grid.cell_nodes(CellId(2))}));
  EXPECT_EQ(r2b.nonmanifold_nodes, 1);
  EXPECT_EQ(r2b.unreferenced_nodes, 2);

  // 3D: two cubes sharing an edge only; two sharing a node only.
  const HexMesh block = make_hex_grid(2, 2, 1);
  const auto r_edge = check_mesh(without(block, {1, 2}));
  EXPECT_EQ(r_edge.nonmanifold_nodes, 2);  // both ends of the shared edge
  const HexMesh cube8 = make_hex_grid(2, 2, 2);
  const auto r_node = check_mesh(without(cube8, {1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(r_node.nonmanifold_nodes, 1);
  EXPECT_EQ(r_node.first_nonmanifold.at(0).node, NodeId(13));
}

TEST(MeshCheck, LinkThatIsAnAnnulus) {
  // Six of the eight cells around the centre node of a 2x2x2 block: the star is connected
  // through faces, but the boundary around the node is two separate cycles.
  const auto r = check_mesh(without(make_hex_grid(2, 2, 2), {0, 7}));
  EXPECT_EQ(r.nonmanifold_nodes, 1);
  EXPECT_EQ(r.first_nonmanifold.at(0).node, NodeId(13));
  EXPECT_EQ(r.hanging_nodes, 0);
  EXPECT_EQ(r.unreferenced_nodes, 2);  // the corners of the removed cells
}

TEST(MeshCheck, PinchedEdgeUnderAConnectedStar) {
  // Bottom layer of a 2x2x2 block with two diagonal cells only, the top layer full: the
  // vertical edge (1,1,0)-(1,1,1) is pinched. The star of its upper end is connected through
  // the top layer, but its boundary faces meet four times at (1,1,0): not one fan.
  const auto r = check_mesh(without(make_hex_grid(2, 2, 2), {1, 2}));
  EXPECT_EQ(r.nonmanifold_nodes, 2);
  ASSERT_EQ(r.first_nonmanifold.size(), 2u);
  EXPECT_EQ(r.first_nonmanifold[0].node, NodeId(4));   // (1,1,0): star of two cells on an edge
  EXPECT_EQ(r.first_nonmanifold[1].node, NodeId(13));  // (1,1,1)
}

TEST(MeshCheck, LargeGridIsFast) {
  // Linear-time candidates: 27k cells in well under a second.
  const HexMesh m = make_hex_grid(30, 30, 30);
  const auto r = check_mesh(m);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.boundary_faces, 6 * 900);
}

TEST(MeshCheck, ListsAreCapped) {
  const HexMesh grid = make_hex_grid(3, 3, 3);
  std::vector<Vec3> pts = grid.points();
  std::vector<H> cells;
  for (CellId c : id_range<CellId>(grid.n_cells())) cells.push_back(grid.cell_nodes(c));
  for (int i = 0; i < 20; ++i) pts.emplace_back(10 + i, 0, 0);
  MeshCheckOptions o;
  o.max_listed = 3;
  const auto r = check_mesh(HexMesh(pts, cells), o);
  EXPECT_EQ(r.unreferenced_nodes, 20);
  EXPECT_EQ(r.first_unreferenced.size(), 3u);
}

TEST(MeshCheck, SameListsWhateverTheThreadCount) {
  // Every other node of a grid duplicated as an unreferenced copy: many offenders of two
  // kinds, listed the same way by 1 and 2 threads.
  const HexMesh grid = make_hex_grid(6, 5, 4);
  std::vector<Vec3> pts = grid.points();
  for (std::size_t n = 0; n < grid.points().size(); n += 2) pts.push_back(grid.points()[n]);
  std::vector<H> cells;
  for (CellId c : id_range<CellId>(grid.n_cells())) cells.push_back(grid.cell_nodes(c));
  const HexMesh m(pts, cells);
  MeshCheckOptions o;
  o.max_listed = 1000;
  set_threads(1);
  const auto a = check_mesh(m, o);
  set_threads(2);
  const auto b = check_mesh(m, o);
  set_threads(0);
  EXPECT_EQ(a.duplicate_nodes, 105);
  EXPECT_EQ(a.unreferenced_nodes, 105);
  ASSERT_EQ(a.first_duplicates.size(), b.first_duplicates.size());
  for (std::size_t i = 0; i < a.first_duplicates.size(); ++i) {
    EXPECT_EQ(a.first_duplicates[i].node, b.first_duplicates[i].node);
    EXPECT_EQ(a.first_duplicates[i].other, b.first_duplicates[i].other);
  }
  EXPECT_EQ(a.first_duplicates[0].other, NodeId(0));
}

}  // namespace
}  // namespace hexadapt
