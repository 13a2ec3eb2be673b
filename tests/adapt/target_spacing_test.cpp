// Targets pushed apart for the size criterion (target_spacing.h) on hand-made cases.
#include "hexadapt/adapt/target_spacing.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"
#include "hexadapt/adapt/controlled_move.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

using test::node_at;

// Unit squares 3 x 1; the nodes (1, 1) and (2, 1) get targets on the line y = 1, `gap` apart
// around x = 1.5.
struct TwoTargets {
  QuadMesh mesh = make_quad_grid(3, 1);
  CellMaterials material = CellMaterials(3, 0);
  Targets targets;
  NodeId a, b;
  explicit TwoTargets(double gap) {
    targets = test::one_target(mesh, Vec3(1, 1, 0), Vec3(1.5 - gap / 2, 1, 0));
    a = node_at(mesh, Vec3(1, 1, 0));
    b = node_at(mesh, Vec3(2, 1, 0));
    targets.has[b] = 1;
    targets.position[b] = Vec3(1.5 + gap / 2, 1, 0);
    targets.interface[a].add(Vec3(0, 1, 0));
    targets.interface[b].add(Vec3(0, 1, 0));
  }
  IdVector<NodeId, NodeConstraint> sliding() const {
    return sliding_constraints(boundary_constraints(mesh), targets);
  }
};

TEST(TargetSpacing, TargetsCloserThanTheShortestEdgeArePushedApartAlongTheirInterface) {
  TwoTargets t(0.02);
  const SizeCriterion size = size_criterion(t.mesh, 0.1);  // shortest edge 0.1
  const TargetSpacingResult r = space_targets(t.mesh, t.material, size, t.sliding(), t.targets);
  EXPECT_EQ(r.short_edges, 1);
  EXPECT_EQ(r.moved, 2);
  EXPECT_EQ(r.left_short, 0);
  const Vec3 pa = t.targets.position[t.a], pb = t.targets.position[t.b];
  EXPECT_NEAR((pb - pa).norm(), 0.125, 1e-12);   // margin 1.25 x 0.1
  EXPECT_NEAR(0.5 * (pa + pb).x(), 1.5, 1e-12);  // each moved half of the way
  EXPECT_DOUBLE_EQ(pa.y(), 1.0);                 // still on the interface line
  EXPECT_DOUBLE_EQ(pb.y(), 1.0);
  EXPECT_NEAR(r.max_shift, (0.125 - 0.02) / 2, 1e-12);  // in local sizes, here 1

  // Both on their targets, the cells keep the criterion: the move reaches them.
  const MoveResult m = controlled_move(t.mesh, t.targets, {}, {}, size);
  EXPECT_EQ(m.n_reached, 2);
  EXPECT_TRUE(failing_cells(t.mesh, 0.3, size).empty());
}

TEST(TargetSpacing, WithoutItTheSameTargetsCannotBothBeReached) {
  TwoTargets t(0.02);
  const SizeCriterion size = size_criterion(t.mesh, 0.1);
  const MoveResult m = controlled_move(t.mesh, t.targets, {}, {}, size);
  EXPECT_LT(m.n_reached, 2);
}

TEST(TargetSpacing, AFixedTargetStaysAndItsNeighbourMovesTheWholeWay) {
  TwoTargets t(0.02);
  t.targets.interface[t.a].add(Vec3(1, 0, 0));  // a triple point: fixed in 2D
  const SizeCriterion size = size_criterion(t.mesh, 0.1);
  const TargetSpacingResult r = space_targets(t.mesh, t.material, size, t.sliding(), t.targets);
  EXPECT_EQ(r.moved, 1);
  EXPECT_EQ(t.targets.position[t.a], Vec3(1.49, 1, 0));
  EXPECT_NEAR(t.targets.position[t.b].x(), 1.49 + 0.125, 1e-12);
}

TEST(TargetSpacing, NothingMovesWhenTheTargetsAreFarEnoughOrTheCriterionIsOff) {
  TwoTargets far(0.2);
  const IdVector<NodeId, Vec3> before = far.targets.position;
  const TargetSpacingResult r = space_targets(far.mesh, far.material, size_criterion(far.mesh, 0.1),
                                              far.sliding(), far.targets);
  EXPECT_EQ(r.short_edges, 0);
  EXPECT_EQ(r.moved, 0);
  for (NodeId n : id_range<NodeId>(far.mesh.n_nodes()))
    EXPECT_EQ(far.targets.position[n], before[n]);

  TwoTargets off(0.02);
  const TargetSpacingResult o = space_targets(off.mesh, off.material, size_criterion(off.mesh, 0.0),
                                              off.sliding(), off.targets);
  EXPECT_EQ(o.short_edges, 0);
  EXPECT_EQ(o.moved, 0);
}

TEST(TargetSpacing, TwoFixedTargetsAreLeftShortAndSaidSo) {
  TwoTargets t(0.02);
  t.targets.interface[t.a].add(Vec3(1, 0, 0));
  t.targets.interface[t.b].add(Vec3(1, 0, 0));
  const TargetSpacingResult r =
      space_targets(t.mesh, t.material, size_criterion(t.mesh, 0.1), t.sliding(), t.targets);
  EXPECT_EQ(r.short_edges, 1);
  EXPECT_EQ(r.left_short, 1);
  EXPECT_EQ(r.moved, 0);
}

// Unit squares 2 x 2, the top left one of material 1: the edge from u = (1, 1) to v = (1, 2)
// is a riser of the staircase. Its two targets lie on a line y = 1.5 across it, 0.1 apart,
// u's on the side `u_side` (-1: left, +1: right).
struct Riser {
  QuadMesh mesh = make_quad_grid(2, 2);
  CellMaterials material = CellMaterials(4, 0);
  Targets targets;
  NodeId u, v;
  explicit Riser(double u_side) {
    material[CellId(2)] = 1;  // cells in rows: (0, 1) is the third
    u = node_at(mesh, Vec3(1, 1, 0));
    v = node_at(mesh, Vec3(1, 2, 0));
    targets = test::one_target(mesh, Vec3(1, 1, 0), Vec3(1 + 0.05 * u_side, 1.5, 0));
    targets.has[v] = 1;
    targets.position[v] = Vec3(1 - 0.05 * u_side, 1.5, 0);
    targets.interface[u].add(Vec3(0, 1, 0));
    targets.interface[v].add(Vec3(0, 1, 0));
  }
  // The turn from the edge u -> v to a point of material 1 (z of their cross product): > 0 in
  // the grid; on the targets, with material 1 above the line y = 1.5, > 0 when the riser's
  // cells keep their orientation.
  double turn_to_material_1() const {
    const Vec3 tu = targets.position[u];
    return (targets.position[v] - tu).cross(Vec3(1, 2, 0) - tu).z();
  }
};

TEST(TargetSpacing, TargetsThatWouldTurnTheirCellsInsideOutAreSwapped) {
  // Material 1 lies up and to the left of the riser: with u's target right of v's, the riser
  // would turn clockwise onto the interface, its cells the wrong way round.
  Riser crossed(+1);
  EXPECT_LT(crossed.turn_to_material_1(), 0);
  const TargetSpacingResult r = space_targets(
      crossed.mesh, crossed.material, size_criterion(crossed.mesh, 0.1),
      sliding_constraints(boundary_constraints(crossed.mesh), crossed.targets), crossed.targets);
  EXPECT_EQ(r.swapped, 1);
  EXPECT_NEAR(crossed.targets.position[crossed.u].x(), 0.95, 1e-12);
  EXPECT_NEAR(crossed.targets.position[crossed.v].x(), 1.05, 1e-12);
  EXPECT_GT(crossed.turn_to_material_1(), 0);

  Riser kept(-1);  // already in the order that keeps the cells' orientation
  EXPECT_GT(kept.turn_to_material_1(), 0);
  const IdVector<NodeId, Vec3> before = kept.targets.position;
  const TargetSpacingResult k = space_targets(
      kept.mesh, kept.material, size_criterion(kept.mesh, 0.1),
      sliding_constraints(boundary_constraints(kept.mesh), kept.targets), kept.targets);
  EXPECT_EQ(k.swapped, 0);
  EXPECT_EQ(kept.targets.position[kept.u], before[kept.u]);

  TargetSpacingOptions off;  // the option turns it off
  off.uncross = false;
  Riser unswapped(+1);
  EXPECT_EQ(
      space_targets(unswapped.mesh, unswapped.material, size_criterion(unswapped.mesh, 0.1),
                    sliding_constraints(boundary_constraints(unswapped.mesh), unswapped.targets),
                    unswapped.targets, off)
          .swapped,
      0);
}

}  // namespace
}  // namespace hexadapt
