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
  const TargetSpacingResult r = space_targets(t.mesh, size, t.sliding(), t.targets);
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
  const TargetSpacingResult r = space_targets(t.mesh, size, t.sliding(), t.targets);
  EXPECT_EQ(r.moved, 1);
  EXPECT_EQ(t.targets.position[t.a], Vec3(1.49, 1, 0));
  EXPECT_NEAR(t.targets.position[t.b].x(), 1.49 + 0.125, 1e-12);
}

TEST(TargetSpacing, NothingMovesWhenTheTargetsAreFarEnoughOrTheCriterionIsOff) {
  TwoTargets far(0.2);
  const IdVector<NodeId, Vec3> before = far.targets.position;
  const TargetSpacingResult r =
      space_targets(far.mesh, size_criterion(far.mesh, 0.1), far.sliding(), far.targets);
  EXPECT_EQ(r.short_edges, 0);
  EXPECT_EQ(r.moved, 0);
  for (NodeId n : id_range<NodeId>(far.mesh.n_nodes()))
    EXPECT_EQ(far.targets.position[n], before[n]);

  TwoTargets off(0.02);
  const TargetSpacingResult o =
      space_targets(off.mesh, size_criterion(off.mesh, 0.0), off.sliding(), off.targets);
  EXPECT_EQ(o.short_edges, 0);
  EXPECT_EQ(o.moved, 0);
}

TEST(TargetSpacing, TwoFixedTargetsAreLeftShortAndSaidSo) {
  TwoTargets t(0.02);
  t.targets.interface[t.a].add(Vec3(1, 0, 0));
  t.targets.interface[t.b].add(Vec3(1, 0, 0));
  const TargetSpacingResult r =
      space_targets(t.mesh, size_criterion(t.mesh, 0.1), t.sliding(), t.targets);
  EXPECT_EQ(r.short_edges, 1);
  EXPECT_EQ(r.left_short, 1);
  EXPECT_EQ(r.moved, 0);
}

}  // namespace
}  // namespace hexadapt
