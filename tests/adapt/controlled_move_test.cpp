#include "hexadapt/adapt/controlled_move.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"
#include "adapt/generated_case.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {
namespace {

using test::sample_fractions;

template <class M>
Targets targets_of(const M& mesh, const test::Shape& shape, int n_materials, int s = 8) {
  const Fractions f = sample_fractions(mesh, shape, n_materials, s);
  return compute_targets(mesh, f, majority_materials(f), boundary_constraints(mesh));
}

test::Shape disk(const Vec3& centre, double r) {
  return [=](const Vec3& p) {
    Vec3 d = p - centre;
    d.z() = 0;
    return d.norm() < r ? 1 : 0;
  };
}

// Three regions meeting at a point, with a bump: a triple-point-like layout.
test::Shape three_regions(double xs, double ys) {
  return [=](const Vec3& p) {
    if (p.x() < xs + 0.6 * std::sin(p.y())) return 0;
    return p.y() < ys + 0.3 * (p.x() - xs) * (p.x() - xs) / xs ? 1 : 2;
  };
}

template <class M>
void expect_move_keeps_threshold(M mesh, const Targets& t, double threshold) {
  ASSERT_GE(min_quality(mesh), threshold);
  StepSettings shared;
  shared.threshold = threshold;
  const MoveResult r = controlled_move(mesh, t, {}, shared);
  EXPECT_GE(min_quality(mesh), threshold);
  EXPECT_GT(r.n_moving, 0);
  EXPECT_NEAR(r.dist, target_distance(mesh, t), 1e-12);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (r.reached[n]) {
      EXPECT_EQ(mesh.point(n), t.position[n]);
    }
}

TEST(ControlledMove, MovesEveryNodeAllTheWayWhenNothingBlocks) {
  QuadMesh mesh = make_quad_grid(10, 6);
  const Targets t = targets_of(
      mesh, [](const Vec3& p) { return p.x() < 4.3; }, 2);
  const MoveResult r = controlled_move(mesh, t);
  EXPECT_EQ(r.n_moving, 7);
  EXPECT_EQ(r.n_reached, r.n_moving);
  EXPECT_EQ(r.dist, 0.0);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (t.has[n]) {
      EXPECT_EQ(mesh.point(n), t.position[n]);
    }
}

TEST(ControlledMove, MovesEveryNodeAllTheWayWhenNothingBlocks3D) {
  HexMesh mesh = make_hex_grid(6, 4, 3);
  const Targets t = targets_of(
      mesh, [](const Vec3& p) { return p.z() < 1.6; }, 2, 6);
  const MoveResult r = controlled_move(mesh, t);
  EXPECT_EQ(r.n_moving, 7 * 5);
  EXPECT_EQ(r.n_reached, r.n_moving);
  EXPECT_EQ(r.dist, 0.0);
}

TEST(ControlledMove, StopsANodeBeforeItsCellsGoBelowTheThreshold) {
  QuadMesh mesh = make_quad_grid(4, 4);
  Targets t;
  t.has.assign(25, 0);
  t.position.resize(25);
  for (NodeId n : id_range<NodeId>(25)) t.position[n] = mesh.point(n);
  const NodeId centre(12);
  t.has[centre] = 1;
  t.position[centre] = Vec3(2.9, 2.9, 0);  // far into a corner: the cells would fold
  const MoveResult r = controlled_move(mesh, t);
  EXPECT_EQ(r.n_reached, 0);
  EXPECT_FALSE(r.reached[centre]);
  EXPECT_GE(min_quality(mesh), 0.3);
  EXPECT_GT(mesh.point(centre).x(), 2.0);  // it moved part of the way
  EXPECT_NEAR(r.dist, (mesh.point(centre) - t.position[centre]).norm(), 1e-12);
}

TEST(ControlledMove, NeverGoesBelowTheThresholdOnCurvedInterfaces) {
  for (double threshold : {0.3, 0.6, 0.9}) {
    const QuadMesh q = make_quad_grid(14, 10);
    expect_move_keeps_threshold(q, targets_of(q, three_regions(5.0, 5.0), 3), threshold);
    const HexMesh extruded = make_hex_grid(14, 10, 3);
    expect_move_keeps_threshold(extruded, targets_of(extruded, three_regions(5.0, 5.0), 3, 4),
                                threshold);
    const HexMesh h = make_hex_grid(7, 7, 7);
    const auto ball = [](const Vec3& p) { return (p - Vec3(3.4, 3.6, 3.5)).norm() < 2.3; };
    expect_move_keeps_threshold(h, targets_of(h, ball, 2, 6), threshold);
  }
}

TEST(ControlledMove, NeverGoesBelowTheThresholdOnJitteredGrids) {
  const QuadMesh q = make_quad_grid(12, 12, test::jittered_points(12, 12, 0, 0.2, 7));
  expect_move_keeps_threshold(q, targets_of(q, disk(Vec3(6.2, 5.8, 0), 3.9), 2), 0.3);
  const HexMesh h = make_hex_grid(8, 8, 4, test::jittered_points(8, 8, 4, 0.15, 3));
  expect_move_keeps_threshold(h, targets_of(h, disk(Vec3(4.2, 3.8, 0), 2.9), 2, 4), 0.3);
}

// Beside cells already below the threshold (a bad input, a pillow layer the move may mend),
// the move keeps every passing cell passing and makes no failing cell worse. Judging by the
// smallest score around the node alone let a passing cell sink to its failing neighbour's.
TEST(ControlledMove, NeverMakesAPassingCellFailNorAFailingOneWorse) {
  const QuadMesh grid = make_quad_grid(14, 14, test::jittered_points(14, 14, 0, 0.35, 5));
  const double threshold = 0.75;
  index_t failing = 0;
  for (CellId c : id_range<CellId>(grid.n_cells())) failing += grid.cell_quality(c) < threshold;
  ASSERT_GT(failing, 10);
  ASSERT_LT(failing, grid.n_cells() - 10);
  QuadMesh mesh = grid;
  StepSettings shared;
  shared.threshold = threshold;
  const MoveResult r =
      controlled_move(mesh, targets_of(grid, disk(Vec3(7.1, 6.8, 0), 4.6), 2), {}, shared);
  EXPECT_GT(r.n_reached, 0);
  for (CellId c : id_range<CellId>(grid.n_cells())) {
    const double before = grid.cell_quality(c), after = mesh.cell_quality(c);
    if (before >= threshold) {
      EXPECT_GE(after, threshold) << "cell " << c.value() << " was passing";
    } else {
      EXPECT_GE(after, before) << "cell " << c.value() << " got worse";
    }
  }
}

// Every case of hexadapt-generate, in each dimension it has, extruded and jittered.
class ControlledMoveOnGeneratedCases : public ::testing::TestWithParam<test::GeneratedCase> {};

TEST_P(ControlledMoveOnGeneratedCases, NeverGoesBelowTheThreshold) {
  test::with_generated_case(
      GetParam(), [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& material) {
        const double threshold = std::min(0.3, min_quality(grid));
        expect_move_keeps_threshold(
            grid, compute_targets(grid, f, material, boundary_constraints(grid)), threshold);
      });
}

INSTANTIATE_TEST_SUITE_P(
    AllCases, ControlledMoveOnGeneratedCases,
    ::testing::Values(
        test::GeneratedCase{"disk", {20, 20}}, test::GeneratedCase{"sphere", {10, 10, 10}},
        test::GeneratedCase{"venn", {20, 20}}, test::GeneratedCase{"venn", {10, 10, 10}},
        test::GeneratedCase{"venn4", {20, 20}}, test::GeneratedCase{"venn4", {10, 10, 10}},
        test::GeneratedCase{"slotted-disk", {24, 24}},
        test::GeneratedCase{"slotted-disk", {12, 12, 12}},
        test::GeneratedCase{"asteroid", {10, 10, 10}}, test::GeneratedCase{"layers", {20, 20}},
        test::GeneratedCase{"layers", {8, 8, 8}},
        test::GeneratedCase{"triple-point", {35, 15}, 2.0},
        test::GeneratedCase{"stir", {30, 15}, 1.0}, test::GeneratedCase{"vortex", {24, 24}},
        test::GeneratedCase{"vortex", {10, 10, 10}}, test::GeneratedCase{"balldrop", {20, 20}},
        test::GeneratedCase{"balldrop", {10, 10, 10}},
        test::GeneratedCase{"triple-point", {28, 12}, 2.0, 3},
        test::GeneratedCase{"stir", {24, 12}, 1.0, 3},
        test::GeneratedCase{"triple-point", {35, 15}, 2.0, 0, 0.2},
        test::GeneratedCase{"asteroid", {10, 10, 10}, -1, 0, 0.2},
        test::GeneratedCase{"stir", {24, 12}, 1.0, 3, 0.2}),
    [](const ::testing::TestParamInfo<test::GeneratedCase>& i) { return test::label(i.param); });

// A thin layer (cells 1 x 0.2, as a pillow layer) under node (1, 1.2), which moves 0.4 along
// it, at threshold 0.8: moving alone, it shears the layer cells, whose scaled Jacobian
// 0.2 / sqrt(0.04 + s^2) reaches 0.8 at a shift s of 0.15 (6 of the 16 steps), and it ends
// 0.3 from its target. No free node is ahead of it (its neighbours along the layer are on the
// domain's sides), so each step after that is refused unless its free neighbours across the
// layer, (1, 1) and (1, 2.2), are dragged along with it: 10 drags, which move them 0.25 and
// leave the layer cells sheared by 0.15, and the node reaches its target.
TEST(ControlledMove, ANodeCarriesItsNeighboursAcrossALayerAlong) {
  const QuadMesh grid =
      make_quad_grid(std::vector<double>{0, 1, 2}, std::vector<double>{0, 1, 1.2, 2.2});
  const Targets t = test::one_target(grid, Vec3(1, 1.2, 0), Vec3(1.4, 1.2, 0));
  const NodeId node = test::node_at(grid, Vec3(1, 1.2, 0));
  const NodeId below = test::node_at(grid, Vec3(1, 1, 0));
  const NodeId above = test::node_at(grid, Vec3(1, 2.2, 0));
  const auto surface = boundary_constraints(grid);
  MoveOptions o;
  o.drag = false;
  StepSettings shared;
  shared.threshold = 0.8;
  QuadMesh alone = grid;
  const MoveResult stopped = controlled_move(alone, t, o, shared, SizeCriterion{}, &surface);
  EXPECT_EQ(stopped.n_reached, 0);
  EXPECT_GT((alone.point(node) - t.position[node]).norm(), 0.2) << alone.point(node).transpose();

  o.drag = true;
  QuadMesh mesh = grid;
  const MoveResult r = controlled_move(mesh, t, o, shared, SizeCriterion{}, &surface);
  EXPECT_EQ(r.n_reached, 1);
  EXPECT_EQ(r.n_drags, 10);
  EXPECT_EQ(mesh.point(node), Vec3(1.4, 1.2, 0));
  EXPECT_NEAR((mesh.point(below) - Vec3(1.25, 1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((mesh.point(above) - Vec3(1.25, 2.2, 0)).norm(), 0, 1e-12);  // on its side
  EXPECT_GE(min_quality(mesh), 0.8);
}

TEST(ControlledMove, GivesTheSamePositionsWhateverTheThreadCount) {
  // Wavy stripes: enough interface nodes that the colour classes run on several threads.
  const HexMesh start = make_hex_grid(60, 40, 3);
  const auto stripes = [](const Vec3& p) {
    return static_cast<int>(std::floor((p.x() + 0.8 * std::sin(0.5 * p.y())) / 4.7)) % 3;
  };
  const Targets t = targets_of(start, stripes, 3, 3);
  MoveOptions o;
  o.steps = 4;  // few rounds: each parallel region is slow on a loaded machine
  StepSettings shared;
  shared.threshold = 0.7;
  set_threads(1);
  HexMesh a = start;
  const MoveResult ra = controlled_move(a, t, o, shared);
  set_threads(2);
  HexMesh b = start;
  const MoveResult rb = controlled_move(b, t, o, shared);
  set_threads(0);
  EXPECT_EQ(a.points(), b.points());
  EXPECT_EQ(ra.dist, rb.dist);
  EXPECT_LT(ra.n_reached, ra.n_moving);  // the threshold does block some nodes here
}

TEST(DirectMove, PutsEveryNodeOnItsTarget) {
  QuadMesh mesh = make_quad_grid(8, 8);
  const Targets t = targets_of(mesh, disk(Vec3(4.1, 3.9, 0), 2.7), 2);
  const MoveResult r = direct_move(mesh, t);
  EXPECT_EQ(r.n_reached, t.n_interface_nodes);
  EXPECT_EQ(r.dist, 0.0);
}

}  // namespace
}  // namespace hexadapt
