#include "hexadapt/adapt/reach_surface.h"

#include <gtest/gtest.h>

#include "hexadapt/adapt/controlled_move.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

constexpr double threshold = 0.95;
constexpr double near = 0.05;
constexpr double lift = 0.6;

// A 4^3 grid of unit cubes whose middle node has a target `lift` above it on the plane z =
// 2 + lift, the other nodes none: a corner lifted alone leaves the cells beside it at
// 1 / sqrt(1 + lift^2), 0.857, below the threshold; its edge neighbours dragged along, the
// cells beyond them; the plane z = 2 lifted whole keeps every cell a box.
struct Lifted {
  HexMesh mesh = make_hex_grid(4, 4, 4);
  NodeId middle;
  Targets targets;
  SizeCriterion size = size_criterion(mesh, 0.1);
  IdVector<NodeId, NodeConstraint> surface;

  // `normal`: the middle node's interface plane's.
  explicit Lifted(const Vec3& normal = Vec3::UnitZ()) {
    const auto nn = static_cast<std::size_t>(mesh.n_nodes());
    targets.has.assign(nn, 0);
    targets.interface.assign(nn, NodeConstraint{});
    for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
      targets.position.push_back(mesh.point(v));
      if (mesh.point(v) == Vec3(2, 2, 2)) middle = v;
    }
    targets.has[middle] = 1;
    targets.position[middle] += Vec3(0, 0, lift);
    targets.interface[middle].add(normal);
    surface = sliding_constraints(boundary_constraints(mesh), targets);
  }
  double off() const {
    return surface_distance(mesh.point(middle), targets.position[middle], surface[middle]);
  }
};

double min_score(const HexMesh& mesh, const SizeCriterion& size) {
  double s = 1;
  for (CellId c : id_range<CellId>(mesh.n_cells())) s = std::min(s, cell_score(mesh, c, size));
  return s;
}

// The controlled move (with its drags and slides) leaves the node where it is; the repair
// lifts the cells around it with it, and every cell keeps the threshold.
TEST(ReachSurface, ANodeTheMoveLeftShortReachesItsSurfaceWithItsNeighbours) {
  Lifted g;
  StepSettings shared;
  shared.threshold = threshold;
  const MoveResult m = controlled_move(g.mesh, g.targets, {}, shared, g.size, &g.surface);
  EXPECT_EQ(m.n_reached, 0);
  EXPECT_EQ(m.n_slid, 0);
  EXPECT_GT(g.off(), near) << g.off();

  const HexMesh before = g.mesh;
  const ReachResult r =
      reach_surfaces(g.mesh, g.targets, g.surface, g.size, {}, {}, threshold, near);
  EXPECT_EQ(r.off_surface, 1);
  EXPECT_EQ(r.still_off, 0);
  EXPECT_GE(r.passes, 1);
  EXPECT_LE(g.off(), near);
  EXPECT_GE(min_score(g.mesh, g.size), threshold);
  // Nodes kept to the domain's boundary stay on it; its corners do not move.
  for (NodeId v : id_range<NodeId>(g.mesh.n_nodes())) {
    if (v == g.middle) continue;
    const Vec3 d = g.mesh.point(v) - before.point(v);
    EXPECT_NEAR((d - g.surface[v].project(d)).norm(), 0.0, 1e-12) << v.value();
  }
}

TEST(ReachSurface, NoPassLeavesTheMeshAsItIs) {
  Lifted g;
  const HexMesh before = g.mesh;
  ReachOptions o;
  o.passes = 0;
  const ReachResult r =
      reach_surfaces(g.mesh, g.targets, g.surface, g.size, o, {}, threshold, near);
  EXPECT_EQ(r.off_surface, 1);
  EXPECT_EQ(r.still_off, 1);
  EXPECT_EQ(r.passes, 0);
  for (NodeId v : id_range<NodeId>(g.mesh.n_nodes())) EXPECT_EQ(g.mesh.point(v), before.point(v));

  o.passes = -1;
  EXPECT_THROW(reach_surfaces(g.mesh, g.targets, g.surface, g.size, o, {}, threshold, near),
               OptionError);
}

// The middle node is on its surface, the plane x = 2, and half of `lift` short of its target
// on it; the nodes at z = 1 and z = 3 have targets where they are. Alone on its target, the
// middle node leaves the cells around it at 1 / sqrt(1 + 0.3^2), 0.958, below the target
// threshold; the 8 nodes without a target sharing a cell with it, lifted with it, keep every
// cell above it.
constexpr double target_threshold = 0.97;

struct OnItsSurface : Lifted {
  OnItsSurface() : Lifted(Vec3::UnitX()) {
    targets.position[middle] -= Vec3(0, 0, lift / 2);
    for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
      if (mesh.point(v).z() == 1 || mesh.point(v).z() == 3) targets.has[v] = 1;
    surface = sliding_constraints(boundary_constraints(mesh), targets);
  }
  double short_by() const { return (mesh.point(middle) - targets.position[middle]).norm(); }
};

// The node goes onto its target with the nodes without a target repairing its cells; the
// nodes with a target stay on theirs.
TEST(ReachTargets, ANodeOnItsSurfaceReachesItsTargetAndNoOtherTargetMoves) {
  OnItsSurface g;
  EXPECT_EQ(g.off(), 0);
  HexMesh alone = g.mesh;
  alone.set_point(g.middle, g.targets.position[g.middle]);
  EXPECT_LT(min_score(alone, g.size), target_threshold);

  const HexMesh before = g.mesh;
  const ReachResult r =
      reach_targets(g.mesh, g.targets, g.surface, g.size, {}, {}, target_threshold);
  EXPECT_EQ(r.off_surface, 1);
  EXPECT_EQ(r.still_off, 0);
  EXPECT_GE(r.moves, 1);
  EXPECT_EQ(g.short_by(), 0);
  EXPECT_GE(min_score(g.mesh, g.size), target_threshold);
  index_t helpers_moved = 0;
  for (NodeId v : id_range<NodeId>(g.mesh.n_nodes())) {
    if (v == g.middle) continue;
    if (g.targets.has[v]) {
      EXPECT_EQ(g.mesh.point(v), before.point(v)) << v.value();
    }
    helpers_moved += g.mesh.point(v) != before.point(v);
  }
  EXPECT_GT(helpers_moved, 0);
}

// With every other node holding a target, nothing may repair the cells: the node stays.
TEST(ReachTargets, ANodeWhoseCellsOnlyNodesWithATargetCouldRepairStays) {
  OnItsSurface g;
  for (NodeId v : id_range<NodeId>(g.mesh.n_nodes())) g.targets.has[v] = 1;
  const HexMesh before = g.mesh;
  const ReachResult r =
      reach_targets(g.mesh, g.targets, g.surface, g.size, {}, {}, target_threshold);
  EXPECT_EQ(r.off_surface, 1);
  EXPECT_EQ(r.still_off, 1);
  EXPECT_EQ(r.moves, 0);
  for (NodeId v : id_range<NodeId>(g.mesh.n_nodes())) EXPECT_EQ(g.mesh.point(v), before.point(v));
}

}  // namespace
}  // namespace hexadapt
