#include "hexadapt/adapt/smoothing.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"

namespace hexadapt {
namespace {

IdVector<NodeId, char> all_movable(index_t n) {
  return IdVector<NodeId, char>(static_cast<std::size_t>(n), 1);
}

TEST(Smoothing, RepairsAPulledNodeAndNeverLowersTheMinimum) {
  QuadMesh mesh = make_quad_grid(4, 4);
  mesh.set_point(NodeId(12), Vec3(2.8, 2.7, 0));  // the centre node, dragged into a corner
  const double before = min_quality(mesh);
  const SmoothResult r = smooth(mesh, all_movable(mesh.n_nodes()), boundary_constraints(mesh));
  EXPECT_GT(r.moves, 0);
  EXPECT_GT(min_quality(mesh), before);
  EXPECT_GT(min_quality(mesh), 0.9);
}

// Cells at or above the floor stay there, where the local minimum alone lets a node beside a
// poor cell it cannot mend (its other nodes fixed) sink its other cells to that cell's score.
TEST(Smoothing, NoCellSinksBelowTheFloor) {
  // A 5x5 grid: the ring of nodes around the 2x2 inner nodes is jittered and fixed.
  const std::vector<Vec3> jittered = test::jittered_points(5, 5, 0, 0.45, 4);
  QuadMesh grid = make_quad_grid(5, 5);
  IdVector<NodeId, char> movable = all_movable(grid.n_nodes());
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) {
    const Vec3 p = grid.point(v);
    const bool inner = p.x() > 0.5 && p.x() < 4.5 && p.y() > 0.5 && p.y() < 4.5;
    const bool ring = inner && (p.x() < 1.5 || p.x() > 3.5 || p.y() < 1.5 || p.y() > 3.5);
    if (ring) grid.set_point(v, jittered[v.idx()]);
    movable[v] = inner && !ring;
  }
  const double floor = 0.6;
  auto sunk = [&](const QuadMesh& m) {
    index_t n = 0;
    for (CellId c : id_range<CellId>(grid.n_cells()))
      n += grid.cell_quality(c) >= floor && m.cell_quality(c) < floor;
    return n;
  };
  QuadMesh free = grid;
  smooth(free, movable, boundary_constraints(grid));
  ASSERT_GT(sunk(free), 0) << "the case no longer shows the effect";
  QuadMesh floored = grid;
  SmoothOptions o;
  o.floor = floor;
  smooth(floored, movable, boundary_constraints(grid), o);
  EXPECT_EQ(sunk(floored), 0);
  EXPECT_GE(min_quality(floored), min_quality(grid));
}

TEST(Smoothing, KeepsFixedNodesAndBoundaryNodesOnTheBoundary) {
  const int n = 6;
  HexMesh mesh = make_hex_grid(n, n, n, test::jittered_points(n, n, n, 0.3, 11));
  // Also slide the boundary nodes along their faces, off the lattice.
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    Vec3 p = mesh.point(v);
    for (int a = 0; a < 3; ++a) {
      const bool on = p[a] == 0 || p[a] == n;
      if (!on) continue;
      const int b = (a + 1) % 3;
      if (p[b] > 0 && p[b] < n) p[b] += 0.2 * std::sin(3.0 * p[b] + a);
    }
    mesh.set_point(v, p);
  }
  const HexMesh start = mesh;
  const NodeId pinned(3 + 7 * (3 + 7 * 3));  // an interior node
  IdVector<NodeId, char> movable;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) movable.push_back(v != pinned);
  const double before = min_quality(mesh);
  const auto constraint = boundary_constraints(mesh);
  smooth(mesh, movable, constraint);
  EXPECT_GE(min_quality(mesh), before);
  EXPECT_EQ(mesh.point(pinned), start.point(pinned));
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    for (int a = 0; a < 3; ++a) {
      const double x = start.point(v)[a];
      if (x == 0 || x == n) {
        EXPECT_NEAR(mesh.point(v)[a], x, 1e-12);
      }
    }
  // Box corners never move.
  EXPECT_EQ(mesh.point(NodeId(0)), start.point(NodeId(0)));
}

TEST(Smoothing, InterfaceNodesSlideAlongTheirInterface) {
  QuadMesh mesh = make_quad_grid(6, 6);
  // The node column x = 3 is an interface; its nodes are spread unevenly along it.
  IdVector<NodeId, NodeConstraint> constraint = boundary_constraints(mesh);
  for (int j = 1; j < 6; ++j) {
    const NodeId v(3 + 7 * j);
    mesh.set_point(v, Vec3(3.0, j + 0.4 * std::sin(j), 0));
    constraint[v].add(Vec3(1, 0, 0));
  }
  mesh.set_point(NodeId(3 + 7 * 3), Vec3(3.0, 3.8, 0));
  const double before = min_quality(mesh);
  smooth(mesh, all_movable(mesh.n_nodes()), constraint);
  EXPECT_GE(min_quality(mesh), before);
  for (int j = 1; j < 6; ++j) EXPECT_EQ(mesh.point(NodeId(3 + 7 * j)).x(), 3.0);
  EXPECT_LT(std::abs(mesh.point(NodeId(3 + 7 * 3)).y() - 3.0), 0.5);
}

}  // namespace
}  // namespace hexadapt
