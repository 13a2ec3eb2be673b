// The size criterion (size_criterion.h) on small hand-made cases: the score, a move refused
// only because of size, and a pillow layer given enough thickness.
#include "hexadapt/adapt/size_criterion.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"
#include "hexadapt/adapt/controlled_move.h"
#include "hexadapt/adapt/pillow.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

// Two unit squares side by side; node 4 is (1, 1), the top of their shared edge.
QuadMesh two_squares() {
  return make_quad_grid(2, 1);
}

using test::node_at;

// Node (1, 1) heading for (1.95, 1): the right square's top edge shrinks to 0.05 while its
// scaled Jacobian stays 0.725 (both squares' corners are at 0.725 or better all the way).
Targets squeeze_target(const QuadMesh& mesh) {
  return test::one_target(mesh, Vec3(1, 1, 0), Vec3(1.95, 1, 0));
}

TEST(SizeCriterion, LocalSizeIsTheMeanEdgeAndTheScoreDropsBelowEveryJacobian) {
  QuadMesh mesh = make_quad_grid(std::vector<double>{0, 2}, std::vector<double>{0, 1});
  const SizeCriterion size = size_criterion(mesh, 0.6);
  EXPECT_DOUBLE_EQ(size.local_size[CellId(0)], 1.5);
  // Shortest edge 1 < 0.6 x 1.5 = 0.9? No: 1 >= 0.9, the criterion holds: the score is the SJ.
  EXPECT_DOUBLE_EQ(cell_score(mesh, CellId(0), size), 1.0);
  const SizeCriterion strict = size_criterion(mesh, 0.8);  // 1 < 1.2: fails
  EXPECT_NEAR(size_ratio(mesh, CellId(0), strict), 1.0 / 1.2, 1e-12);
  EXPECT_NEAR(cell_score(mesh, CellId(0), strict), -2.0 + 1.0 / 1.2, 1e-12);
  EXPECT_EQ(failing_cells(mesh, 0.3, strict).size(), 1u);
  EXPECT_TRUE(failing_cells(mesh, 0.3, size).empty());
  EXPECT_EQ(cell_score(mesh, CellId(0), SizeCriterion{}), 1.0);  // off: the SJ
}

TEST(SizeCriterion, AMoveIsRefusedOnlyBecauseOfSize) {
  QuadMesh free_mesh = two_squares();
  const Targets t = squeeze_target(free_mesh);
  const MoveResult without = controlled_move(free_mesh, t);
  EXPECT_EQ(without.n_reached, 1);  // the shape alone lets it through
  EXPECT_GE(min_quality(free_mesh), 0.72);
  EXPECT_NEAR(cell_edge_lengths(free_mesh, CellId(1)).min, 0.05, 1e-12);

  QuadMesh mesh = two_squares();
  const SizeCriterion size = size_criterion(mesh, 0.1);
  const MoveResult with = controlled_move(mesh, t, {}, {}, size);
  EXPECT_EQ(with.n_reached, 0);
  // 16 steps of 0.95 / 16: step 15 leaves 1 - 0.95 x 15 / 16 = 0.109 >= 0.1, step 16 not.
  const NodeId top = node_at(mesh, Vec3(1 + 0.95 * 15 / 16, 1, 0));
  ASSERT_TRUE(top.valid());
  EXPECT_TRUE(failing_cells(mesh, 0.3, size).empty());
}

// Given its surface (here the line y = 1 through the target), the node refused at 0.109 from
// the corner slides along it instead: the nearest ring point that keeps the edge >= 0.1 is
// 1/16 of its mean edge length (1) short of the target. (No drag: the other nodes are given
// no constraint here, so the corner ahead would be dragged.)
TEST(SizeCriterion, ANodeRefusedBySizeSlidesOntoItsSurface) {
  QuadMesh mesh = two_squares();
  const Targets t = squeeze_target(mesh);
  IdVector<NodeId, NodeConstraint> surface(static_cast<std::size_t>(mesh.n_nodes()));
  const NodeId top = node_at(mesh, Vec3(1, 1, 0));
  surface[top].add(Vec3(0, 1, 0));
  const SizeCriterion size = size_criterion(mesh, 0.1);
  MoveOptions o;
  o.drag = false;
  const MoveResult r = controlled_move(mesh, t, o, {}, size, &surface);
  EXPECT_EQ(r.n_reached, 0);
  EXPECT_EQ(r.n_slid, 1);
  EXPECT_TRUE(r.on_surface[top]);
  EXPECT_NEAR((mesh.point(top) - Vec3(1.95 - 0.0625, 1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(surface_distance(mesh.point(top), t.position[top], surface[top]), 0, 1e-12);
  EXPECT_TRUE(failing_cells(mesh, 0.3, size).empty());
}

// Three unit squares in a row, node (1, 1) heading for (1.95, 1) along the top side: the
// free node (2, 1) ahead of it stops it at the size criterion, unless it is dragged along.
// Dragged one step at a time, it keeps the edge between them at 1 - 0.95 x 15 / 16 = 0.109
// and ends 0.059 right of where it was; every cell keeps both criteria.
TEST(SizeCriterion, AFreeNodeAheadIsDraggedAlong) {
  const QuadMesh grid = make_quad_grid(3, 1);
  const Targets t = squeeze_target(grid);
  const SizeCriterion size = size_criterion(grid, 0.1);
  const auto surface = boundary_constraints(grid);
  const NodeId ahead = node_at(grid, Vec3(2, 1, 0));
  MoveOptions o;
  o.drag = false;
  QuadMesh stopped = grid;
  const MoveResult without = controlled_move(stopped, t, o, {}, size, &surface);
  EXPECT_EQ(without.n_reached, 0);
  EXPECT_EQ(without.n_drags, 0);
  EXPECT_EQ(stopped.point(ahead), Vec3(2, 1, 0));

  o.drag = true;
  QuadMesh mesh = grid;
  const MoveResult with = controlled_move(mesh, t, o, {}, size, &surface);
  EXPECT_EQ(with.n_reached, 1);
  EXPECT_EQ(with.n_drags, 1);
  EXPECT_EQ(mesh.point(node_at(grid, Vec3(1, 1, 0))), Vec3(1.95, 1, 0));
  EXPECT_NEAR(mesh.point(ahead).x(), 2 + 0.95 / 16, 1e-12);
  EXPECT_EQ(mesh.point(ahead).y(), 1.0);  // it stays on the domain's side
  EXPECT_TRUE(failing_cells(mesh, 0.3, size).empty());
}

TEST(SizeCriterion, APillowLayerIsGivenTheThicknessTheCriterionNeeds) {
  const HexMesh mesh = make_hex_grid(3, 3, 3);
  IdVector<CellId, char> in_set(static_cast<std::size_t>(mesh.n_cells()), 0);
  in_set[CellId(13)] = 1;  // the centre cube
  PillowOptions thin;
  thin.offset = 0.02;  // a layer 0.02 x 0.87 thick: far below 0.1 x the unit size
  const auto boundary = boundary_constraints(mesh);
  const PillowResult<HexMesh> plain = pillow_cells(mesh, in_set, boundary, thin);
  const SizeCriterion size = size_criterion(mesh, 0.1);
  const SizeCriterion plain_size = size.remapped(plain.cell_origin.raw());
  EXPECT_FALSE(failing_cells(plain.mesh, 0.0, plain_size).empty());

  const PillowResult<HexMesh> thick = pillow_cells(mesh, in_set, boundary, thin, size);
  const SizeCriterion thick_size = size.remapped(thick.cell_origin.raw());
  EXPECT_TRUE(failing_cells(thick.mesh, 0.3, thick_size).empty());
  for (CellId c : id_range<CellId>(thick.mesh.n_cells()))
    EXPECT_GE(cell_edge_lengths(thick.mesh, c).min, 1.5 * 0.1 - 1e-12);
}

}  // namespace
}  // namespace hexadapt
