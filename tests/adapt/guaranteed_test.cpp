// The guaranteed pipeline (paper Fig. 10-b) on small generated cases: every output cell keeps
// the threshold, the mesh is valid, the nodes get closer to their targets than after the
// first controlled move, and the result does not depend on the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "adapt/flow_cases.h"
#include "adapt/generated_case.h"
#include "hexadapt/adapt/adapt.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/mesh_check.h"
#include "mesh/scaled_mesh.h"

namespace hexadapt {
namespace {

AdaptOptions guaranteed_options() {
  AdaptOptions o;
  o.method = AdaptMethod::guaranteed;
  return o;
}

template <class M>
void check_guaranteed(const M& grid, const AdaptResult<M>& r, double threshold = 0.3) {
  ASSERT_FALSE(r.stopped_bad_input);
  EXPECT_GE(r.min_quality, threshold);
  EXPECT_EQ(r.n_below_threshold, 0);
  EXPECT_GE(min_quality(r.mesh), threshold);  // independent of the result's own statistics
  const MeshCheckResult check = check_mesh(r.mesh);
  EXPECT_TRUE(check.ok()) << "hanging " << check.hanging_nodes << " inverted "
                          << check.inverted_cells << " nonmanifold " << check.nonmanifold_nodes;
  ASSERT_EQ(r.material.size(), static_cast<std::size_t>(r.mesh.n_cells()));
  for (int m : r.material) EXPECT_TRUE(m >= 0);
  EXPECT_EQ(r.mesh.n_cells(), grid.n_cells() + r.n_interface_layer_cells + r.n_cells_added);
  index_t layer = 0;
  for (const auto& a : r.interface_pillows) layer += a.layer_cells;
  EXPECT_EQ(layer, r.n_interface_layer_cells);
  index_t published = 0;
  for (const auto& a : r.cavities) published += a.published;
  EXPECT_EQ(published, r.n_cavities_published);
  // A first layer kept with its failing cells fails until the moves and the smoothing have
  // mended it (guaranteed_pipeline.cpp); every other step holds the threshold.
  const bool kept_failing = std::any_of(r.interface_pillows.begin(), r.interface_pillows.end(),
                                        [](const auto& a) { return a.failing > 0; });
  for (const auto& s : r.steps) {
    const bool before_mended = s.name == "pillow" || s.name == "move" || s.name == "cavity";
    if (!(kept_failing && before_mended)) {
      EXPECT_GE(s.min_quality, threshold) << s.name;
    }
  }
  // The distance to the surfaces: the last step slides nodes along them, which may take them
  // farther from their target points (the asteroid at 6^3: 0.37 -> 0.48).
  EXPECT_LE(r.surface_dist_final, r.surface_dist_init);
  index_t blocked = 0;
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    EXPECT_EQ(r.blocked[v] != 0, r.has_target[v] && !r.near_interface[v]);
    EXPECT_LE(r.surface_distance[v], r.distance[v] + 1e-12);
    blocked += r.blocked[v] != 0;
  }
  EXPECT_EQ(blocked, r.n_blocked);
  EXPECT_EQ(r.n_near_interface + r.n_blocked, [&] {
    index_t n = 0;
    for (char h : r.has_target) n += h != 0;
    return n;
  }());
}

class GeneratedCases : public ::testing::TestWithParam<test::GeneratedCase> {};

TEST_P(GeneratedCases, KeepTheThresholdAndGetCloser) {
  test::with_generated_case(
      GetParam(), [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& material) {
        const auto r = adapt(grid, f, material, guaranteed_options());
        check_guaranteed(grid, r);
        // Closer than after the first move, unless that move already put every node on its
        // interface.
        if (r.surface_dist_init > 0 && r.n_blocked > 0) {
          EXPECT_LT(r.surface_dist_final, r.surface_dist_init);
        }
      });
}

INSTANTIATE_TEST_SUITE_P(
    Small, GeneratedCases,
    ::testing::Values(
        test::GeneratedCase{"triple-point", {28, 12}, 0.5},
        test::GeneratedCase{"triple-point", {28, 12}, 1.5},
        test::GeneratedCase{"triple-point", {42, 18}, 1.5},
        test::GeneratedCase{"triple-point", {42, 18}, 2.0},
        test::GeneratedCase{"stir", {30, 15}, 0.5}, test::GeneratedCase{"stir", {30, 15}, 2.0},
        test::GeneratedCase{"stir", {40, 20}, 1.0}, test::GeneratedCase{"stir", {24, 24}, 1.0},
        test::GeneratedCase{"triple-point", {21, 9}, 1.0, 3},
        test::GeneratedCase{"stir", {24, 12}, 1.0, 3}, test::GeneratedCase{"vortex", {24, 24}},
        test::GeneratedCase{"venn", {20, 20}}, test::GeneratedCase{"slotted-disk", {24, 24}},
        test::GeneratedCase{"balldrop", {20, 20}}, test::GeneratedCase{"asteroid", {6, 6, 6}},
        test::GeneratedCase{"balldrop", {6, 6, 6}},
        test::GeneratedCase{"venn", {20, 20}, -1, 0, 0.2},
        test::GeneratedCase{"triple-point", {28, 12}, 1.0, 0, 0.2},
        test::GeneratedCase{"stir", {20, 10}, 1.0, 3, 0.2}),
    [](const ::testing::TestParamInfo<test::GeneratedCase>& i) { return test::label(i.param); });

// A true 3D case the paper's cavities leave short and the interfaces pillowed first reach:
// the asteroid at 16^3 (measured: 310 of 506 interface nodes with cavities only, 504 with
// the first layer), both keeping the threshold and the size criterion. (The drop over the
// pool at 12^3 served here until the volume offset of the targets: cavities now reach all
// its 301 nodes.)
// The asteroid at 20^3: with the interfaces pillowed first every interface node reaches its
// surface, where cavities leave a tenth short. The layers kept with the cells that fail on the
// staircase, for the moves to mend, reach more than layers carved where they fail (measured:
// 782, 701 and 767 of 782). Without the last step, which puts the nodes still off their
// surface on it with their neighbours: with it the first layer, kept failing or carved,
// brings all 782 near and cavities 768.
TEST(GuaranteedMethod, InterfacesPillowedFirstReachWhereCavitiesDoNot) {
  test::with_generated_case({"asteroid", {20, 20, 20}}, [](const auto& grid, const Fractions& f,
                                                           const IdVector<CellId, int>& m) {
    AdaptOptions o = guaranteed_options();
    o.reach.passes = 0;
    const auto first = adapt(grid, f, m, o);  // automatic: first in 3D
    check_guaranteed(grid, first);
    EXPECT_EQ(first.n_below_min_edge, 0);
    EXPECT_GT(first.n_interface_layer_cells, 0);
    EXPECT_GE(first.n_near_interface, 0.98 * first.n_interface_nodes);
    ASSERT_FALSE(first.mend_failing.empty());
    EXPECT_EQ(first.mend_failing.back(), 0);
    index_t kept_failing = 0;
    for (const InterfacePillowAttempt& a : first.interface_pillows) kept_failing += a.failing;
    EXPECT_GT(kept_failing, 0);
    o.mend_rounds = 0;
    const auto carved = adapt(grid, f, m, o);
    check_guaranteed(grid, carved);
    EXPECT_TRUE(carved.mend_failing.empty());
    EXPECT_LT(carved.n_near_interface, first.n_near_interface);
    o.layers = LayerStrategy::cavities;
    const auto cavities = adapt(grid, f, m, o);
    check_guaranteed(grid, cavities);
    EXPECT_EQ(cavities.n_interface_layer_cells, 0);
    EXPECT_LT(cavities.n_near_interface, 0.95 * cavities.n_interface_nodes);
  });
}

// The progress names each phase and moves on through every run: on the vortex at 12^3 and
// t = 1.5 the first layer is mended (3 runs), and the bar, which said "adapt" at 30 %
// through all of it, names the runs and the rounds of the move-smooth loop, never going back.
TEST(GuaranteedMethod, ReportsItsPhasesAndMovesOnThroughEveryRun) {
  test::with_generated_case({"vortex", {12, 12, 12}, 1.5}, [](const auto& grid, const Fractions& f,
                                                              const IdVector<CellId, int>& m) {
    for (AdaptMethod method : {AdaptMethod::guaranteed, AdaptMethod::base}) {
      std::vector<std::pair<std::string, double>> seen;
      AdaptOptions o;
      o.method = method;
      o.progress = [&](std::string_view phase, double fraction) {
        seen.emplace_back(std::string(phase), fraction);
      };
      const auto r = adapt(grid, f, m, o);
      ASSERT_GE(seen.size(), 5u);
      EXPECT_EQ(seen.front().second, 0.0);
      EXPECT_EQ(seen.back(), std::make_pair(std::string("done"), 1.0));
      for (std::size_t k = 1; k < seen.size(); ++k) {
        EXPECT_LE(seen[k - 1].second, seen[k].second) << seen[k].first;
        if (k + 1 < seen.size()) {
          EXPECT_LT(seen[k].second, 1.0) << seen[k].first;
        }
      }
      auto has = [&](const std::string& phase) {
        return std::any_of(seen.begin(), seen.end(),
                           [&](const auto& p) { return p.first == phase; });
      };
      if (method == AdaptMethod::base) {
        for (const char* phase : {"targets", "move", "pillow", "smooth"}) {
          EXPECT_TRUE(has(phase)) << phase;
        }
        continue;
      }
      ASSERT_GE(r.mend_failing.size(), 2u);
      const std::string last = "run " + std::to_string(r.mend_failing.size()) + ": ";
      for (const std::string& phase :
           {std::string("check"), std::string("targets"), std::string("run 1: pillow"),
            std::string("run 1: move"), std::string("run 1: mend"), std::string("run 2: pillow"),
            last + "move-smooth 1", last + "move-smooth 2"}) {
        EXPECT_TRUE(has(phase)) << phase;
      }
      std::set<double> fractions;
      for (const auto& p : seen) fractions.insert(p.second);
      EXPECT_GE(fractions.size(), 12u);
    }
  });
}

// Each material's output volume over its input volume (sum of fraction x cell volume) - 1.
template <class M>
std::vector<double> volume_errors(const M& grid, const Fractions& f, const AdaptResult<M>& r) {
  std::vector<double> in(static_cast<std::size_t>(f.n_materials()), 0), out(in.size(), 0);
  for (CellId c : id_range<CellId>(grid.n_cells()))
    for (int a = 0; a < f.n_materials(); ++a)
      in[static_cast<std::size_t>(a)] += f(c, a) * grid.cell_volume(c);
  for (CellId c : id_range<CellId>(r.mesh.n_cells()))
    out[static_cast<std::size_t>(r.material[c])] += r.mesh.cell_volume(c);
  for (std::size_t a = 0; a < in.size(); ++a) out[a] = out[a] / in[a] - 1;
  return out;
}

// The targets' volume offset in 3D: on the asteroid at 16^3 the core ended 6.1 % short with
// its targets on the fractions' planes (its staircase cut at every corner); with the offset
// every material is within 1 % (measured: core -0.29 %), as many nodes reach their
// interface, and the guarantee holds.
TEST(GuaranteedMethod, TheVolumeOffsetKeepsEveryMaterialsVolume) {
  test::with_generated_case({"asteroid", {16, 16, 16}}, [](const auto& grid, const Fractions& f,
                                                           const IdVector<CellId, int>& m) {
    AdaptOptions o = guaranteed_options();
    const auto with = adapt(grid, f, m, o);
    o.targets.volume_offset = VolumeOffset::off;
    const auto without = adapt(grid, f, m, o);
    check_guaranteed(grid, with);
    EXPECT_EQ(with.n_below_min_edge, 0);
    EXPECT_GE(with.n_near_interface, without.n_near_interface);
    const auto e_with = volume_errors(grid, f, with), e_without = volume_errors(grid, f, without);
    for (double e : e_with) EXPECT_LT(std::abs(e), 0.01);
    EXPECT_LT(e_without[2], -0.03) << "the core must lose volume without the offset";
  });
}

// --layers automatic in 3D: without drags, a first layer leaves many nodes of an extruded 2D
// case off their interface, so cavities run too and, reaching more, are kept; with an
// enough_share of 0 the first layer is kept without trying them. (With drags the first layer
// brings enough of them near on this case.)
TEST(GuaranteedMethod, AutomaticLayersFallBackToCavitiesWhereTheFirstLayerFallsShort) {
  test::with_generated_case(
      {"triple-point", {35, 15}, 2.0, 3},
      [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        AdaptOptions o = guaranteed_options();
        o.move.drag = false;
        o.reach.passes = 0;  // with it, the first layer brings 333 of the 340 nodes near
        const auto r = adapt(grid, f, m, o);
        check_guaranteed(grid, r);
        EXPECT_EQ(r.layers, LayerStrategy::cavities);
        EXPECT_LT(r.other_near_interface, o.enough_share * r.n_interface_nodes);
        EXPECT_GT(r.n_near_interface, r.other_near_interface);
        o.enough_share = 0;
        const auto first = adapt(grid, f, m, o);
        check_guaranteed(grid, first);
        EXPECT_EQ(first.layers, LayerStrategy::first);
        EXPECT_EQ(first.other_near_interface, 0);
        EXPECT_EQ(first.n_near_interface, r.other_near_interface);
      });
}

// The guarantee and the mesh do not depend on the unit or the place: the triple point in
// units from 1e-300 to 1e300, or moved 1e6 away, gives the same assignment, and from it the
// same cells, materials and smallest scaled Jacobian (at 1e-300 squared lengths underflow,
// and at 1e300 volumes overflow, unless the stages compute in the grid's UnitFrame). In a
// power-of-two unit the arithmetic is the same: the mesh is the same to the last bit.
TEST(GuaranteedMethod, TheSameMeshInAnyUnitAndPlace) {
  test::with_generated_case(
      {"triple-point", {35, 15}, 2.0},
      [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        const auto r = adapt(grid, f, m, guaranteed_options());
        for (auto [scale, offset] : {std::pair{1e-300, 0.0},
                                     {1e-20, 0.0},
                                     {1e-6, 0.0},
                                     {1e6, 0.0},
                                     {1e20, 0.0},
                                     {1e300, 0.0},
                                     {1.0, 1e6}}) {
          const auto moved = test::scaled(grid, scale, offset);
          EXPECT_EQ(assign::assign_materials(moved, f).correction.labels.raw(), m.raw())
              << scale << " " << offset;
          const auto s = adapt(moved, f, m, guaranteed_options());
          EXPECT_FALSE(s.stopped_bad_input) << scale << " " << offset;
          EXPECT_EQ(s.mesh.n_cells(), r.mesh.n_cells()) << scale << " " << offset;
          EXPECT_EQ(s.material.raw(), r.material.raw()) << scale << " " << offset;
          EXPECT_NEAR(s.min_quality, r.min_quality, 1e-9) << scale << " " << offset;
          EXPECT_EQ(s.n_near_interface, r.n_near_interface) << scale << " " << offset;
          EXPECT_NEAR(s.mesh.point(NodeId(0)).x(), scale * r.mesh.point(NodeId(0)).x() + offset,
                      1e-9 * scale + 1e-6 * offset);
          EXPECT_NEAR(s.dist_final / scale, r.dist_final, 1e-9 * r.dist_final) << scale;
        }
        for (double scale : {0x1p-1000, 0x1p-20, 0x1p40, 0x1p1000}) {
          const auto s = adapt(test::scaled(grid, scale), f, m, guaranteed_options());
          ASSERT_EQ(s.mesh.n_nodes(), r.mesh.n_nodes()) << scale;
          for (NodeId v : id_range<NodeId>(r.mesh.n_nodes()))
            ASSERT_EQ(s.mesh.point(v), scale * r.mesh.point(v)) << scale << " node " << v.value();
          EXPECT_EQ(s.dist_final, scale * r.dist_final) << scale;
          EXPECT_EQ(s.local_size.raw().front(), scale * r.local_size.raw().front()) << scale;
        }
      });
}

// Where the base method of Fig. 10-a inverts cells (adapt_test.cpp: the extruded triple
// point 35x15x3 at t = 2 ends at -0.004), the guaranteed one keeps the threshold.
TEST(GuaranteedMethod, HoldsWhereTheBaseMethodInvertsCells) {
  test::with_generated_case(
      {"triple-point", {35, 15}, 2.0, 3},
      [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        AdaptOptions base;
        base.method = AdaptMethod::base;
        const auto b = adapt(grid, f, m, base);
        EXPECT_LT(b.min_quality, 0.0);
        const auto r = adapt(grid, f, m, guaranteed_options());
        check_guaranteed(grid, r);
        EXPECT_GT(r.dist_init, 0.0);
        EXPECT_LT(r.dist_final, r.dist_init);
      });
}

// Nodes that stay short of their targets are the price of the guarantee: the result says
// which, and names the worst cells next to them, lowest quality first. A demanding threshold
// makes sure some stay short.
TEST(GuaranteedMethod, ReportsTheNodesItCouldNotMove) {
  const double h = 1.0 / 6;
  const QuadMesh grid = make_quad_grid(42, 18, Vec3::Zero(), Vec3(h, h, 1));
  const Fractions f = test::sample_fractions(grid, test::triple_point(4.0), 3, 12);
  AdaptOptions o = guaranteed_options();
  o.threshold = 0.6;
  o.reach.passes = 0;
  const auto r = adapt(grid, f, majority_materials(f), o);
  check_guaranteed(grid, r, 0.6);
  EXPECT_GT(r.n_blocked, 0);
  ASSERT_FALSE(r.blocking_cells.empty());
  EXPECT_LE(r.blocking_cells.size(), 10u);
  for (std::size_t i = 0; i < r.blocking_cells.size(); ++i) {
    const auto [c, q] = r.blocking_cells[i];
    ASSERT_LT(c.value(), r.mesh.n_cells());
    EXPECT_EQ(q, r.mesh.cell_quality(c));
    if (i > 0) {
      EXPECT_GE(q, r.blocking_cells[i - 1].second);
    }
    bool next_to_blocked = false;
    for (NodeId v : r.mesh.cell_nodes(c)) next_to_blocked |= r.blocked[v] != 0;
    EXPECT_TRUE(next_to_blocked);
  }
}

// The vortex at 16^3 and t = 1.5: its filaments are one cell thick, and the move-smooth loop
// leaves nodes beside them off their surface, held by cells at the threshold (a surface
// distance ratio of 0.18). Put on their surface with their neighbours repairing the cells
// around them, most reach it.
TEST(GuaranteedMethod, NodesTheLoopLeftOffTheirSurfaceReachItWithTheirNeighbours) {
  test::with_generated_case({"vortex", {16, 16, 16}, 1.5}, [](const auto& grid, const Fractions& f,
                                                              const IdVector<CellId, int>& m) {
    AdaptOptions o = guaranteed_options();
    o.reach.passes = 0;
    const auto without = adapt(grid, f, m, o);
    check_guaranteed(grid, without);
    EXPECT_EQ(without.reach.passes, 0);
    EXPECT_GE(without.n_blocked, 5);
    EXPECT_GT(without.surface_dist_final, 0.1 * without.surface_dist_init);

    const auto r = adapt(grid, f, m, guaranteed_options());
    check_guaranteed(grid, r);
    EXPECT_EQ(r.n_below_min_edge, 0);
    EXPECT_EQ(r.reach.off_surface, without.n_blocked);
    EXPECT_LE(r.n_blocked, r.reach.still_off);  // the loop, resumed, may bring more near
    EXPECT_LE(2 * r.n_blocked, without.n_blocked);
    EXPECT_LE(r.surface_dist_final, 0.05 * r.surface_dist_init);
    EXPECT_EQ(r.surface_dist_init, without.surface_dist_init);  // the same run up to the loop
  });
}

// Nodes the controlled move slides onto their surface, short of their target, get a cavity
// as the nodes off their surface do (cavity pillowing is the 2D default), and the cavity
// gives them room to reach their target. Seeded with the nodes off their surface only, these
// cases kept target distance ratios of 0.46 and 0.43 (the triple point at 28x12, t = 1.5,
// and stir at 30x15, t = 2).
TEST(GuaranteedMethod, NodesThatSlidShortOfTheirTargetReachItThroughACavity) {
  for (const test::GeneratedCase& c : {test::GeneratedCase{"triple-point", {28, 12}, 1.5},
                                       test::GeneratedCase{"stir", {30, 15}, 2.0}}) {
    SCOPED_TRACE(test::label(c));
    test::with_generated_case(
        c, [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
          const auto r = adapt(grid, f, m, guaranteed_options());
          check_guaranteed(grid, r);
          EXPECT_EQ(r.n_below_min_edge, 0);
          EXPECT_GT(r.dist_init, 0);
          EXPECT_LE(r.dist_final, 0.01 * r.dist_init);
        });
  }
}

// Stir at 40x20, t = 1, extruded into 2 hex layers: the first layer (the 3D default) leaves 3
// of its 762 interface nodes on their surface short of their targets (target distance ratio
// 0.0115); cavities around them at the end take them there. Some of its targets are closer
// than the size criterion lets their edge be (12 edges), which target_spacing.h pushes apart.
// The loop's smoothing relaxes the nodes to a hundredth of an edge here: with the default
// tenth, no node is left short on this case.
TEST(GuaranteedMethod, AFewNodesLeftShortByTheFirstLayerReachTheirTargetsThroughLateCavities) {
  test::with_generated_case(
      test::GeneratedCase{"stir", {40, 20}, 1.0, 2},
      [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        AdaptOptions relaxed = guaranteed_options();
        relaxed.loop_min_move = 0.01;
        AdaptOptions o = relaxed;
        o.late_cavity_share = 0;
        o.reach.passes = 0;  // the late reach takes them there too
        const auto without = adapt(grid, f, m, o);
        check_guaranteed(grid, without);
        EXPECT_EQ(without.layers, LayerStrategy::first);
        EXPECT_GT(without.dist_final, 0.005 * without.dist_init);
        EXPECT_EQ(without.n_cavities_published, 0);
        EXPECT_GT(without.spacing.short_edges, 0);
        EXPECT_EQ(without.spacing.left_short, 0);

        const auto r = adapt(grid, f, m, relaxed);
        check_guaranteed(grid, r);
        EXPECT_EQ(r.n_below_min_edge, 0);
        EXPECT_EQ(r.late_cavities.short_nodes, 3);
        EXPECT_TRUE(r.late_cavities.tried);
        EXPECT_TRUE(r.late_cavities.kept);
        EXPECT_GT(r.n_cavities_published, 0);
        EXPECT_EQ(r.dist_final, 0);
        EXPECT_EQ(r.n_reached, r.n_interface_nodes);
      });
}

// Late cavities that bring no node closer are dropped: on balldrop at 20x20, t = 2, the one
// node left short gets two cavities, after which the rounds of the loop leave it where it
// was; the output is the one without them.
TEST(GuaranteedMethod, LateCavitiesThatBringNoNodeCloserAreDropped) {
  test::with_generated_case(
      test::GeneratedCase{"balldrop", {20, 20}, 2.0},
      [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        const auto r = adapt(grid, f, m, guaranteed_options());
        check_guaranteed(grid, r);
        EXPECT_EQ(r.late_cavities.short_nodes, 1);
        EXPECT_TRUE(r.late_cavities.tried);
        EXPECT_GT(r.late_cavities.published, 0);
        EXPECT_FALSE(r.late_cavities.kept);
        AdaptOptions o = guaranteed_options();
        o.late_cavity_share = 0;
        const auto without = adapt(grid, f, m, o);
        EXPECT_FALSE(without.late_cavities.tried);
        EXPECT_EQ(r.mesh.n_cells(), without.mesh.n_cells());
        EXPECT_EQ(r.dist_final, without.dist_final);
        EXPECT_EQ(r.n_cavities_published, without.n_cavities_published);
      });
}

// Stir at 56x24, t = 2 (2D): two nodes end on their surface short of their targets, and no
// cavity around them meets both criteria; put on their targets with the nodes without a
// target repairing their cells, they reach them (the late reach; target distance ratio
// 0.007 without it).
TEST(GuaranteedMethod, TheLastNodesShortOfTheirTargetsReachThemWithTheirNeighbours) {
  test::with_generated_case(
      test::GeneratedCase{"stir", {56, 24}, 2.0},
      [](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        AdaptOptions o = guaranteed_options();
        o.reach.passes = 0;
        const auto without = adapt(grid, f, m, o);
        check_guaranteed(grid, without);
        EXPECT_EQ(without.late_cavities.published, 0);
        EXPECT_EQ(without.late_reach.off_surface, 2);
        EXPECT_EQ(without.late_reach.still_off, 2);
        EXPECT_GT(without.dist_final, 0.005 * without.dist_init);

        const auto r = adapt(grid, f, m, guaranteed_options());
        check_guaranteed(grid, r);
        EXPECT_EQ(r.n_below_min_edge, 0);
        EXPECT_EQ(r.late_cavities.published, 0);
        EXPECT_EQ(r.late_reach.off_surface, 2);
        EXPECT_EQ(r.late_reach.still_off, 0);
        EXPECT_EQ(r.dist_final, 0);
        EXPECT_EQ(r.n_reached, r.n_interface_nodes);
        EXPECT_EQ(r.mesh.n_cells(), without.mesh.n_cells());
      });
}

// A triple point extruded into 2 hex layers, with its fractions.
std::pair<HexMesh, Fractions> extruded_triple_point() {
  const double h = 1.0 / 8;
  HexMesh grid = make_hex_grid(28, 12, 2, Vec3::Zero(), Vec3(2 * h, 2 * h, h));
  Fractions f = test::sample_fractions(grid, test::triple_point(7.0), 3, 4);
  return {std::move(grid), std::move(f)};
}

TEST(GuaranteedMethod, HoldsAHigherThresholdInAnExtrudedCase) {
  const auto [grid, f] = extruded_triple_point();
  AdaptOptions o = guaranteed_options();
  o.threshold = 0.5;
  const auto r = adapt(grid, f, majority_materials(f), o);
  check_guaranteed(grid, r, 0.5);
}

// AdaptOptions holds the one threshold (StepSettings) every step keeps.
TEST(GuaranteedMethod, EveryStepKeepsTheOneThreshold) {
  const auto [grid, f] = extruded_triple_point();
  AdaptOptions o = guaranteed_options();
  o.threshold = 0.5;
  o.layers = LayerStrategy::both;  // the interface pillows, the move and the cavities
  const auto r = adapt(grid, f, majority_materials(f), o);
  check_guaranteed(grid, r, 0.5);
  EXPECT_GT(r.n_cells_added, 0);
  EXPECT_GT(r.n_interface_layer_cells, 0);
}

TEST(GuaranteedMethod, StopsOnBadInputUnlessAllowed) {
  // A jittered grid whose cells are all near 0.6: a threshold of 0.9 is not met on input.
  const std::vector<Vec3> p = test::jittered_points(10, 10, 0, 0.3, 7);
  const QuadMesh grid = make_quad_grid(10, 10, p);
  const Fractions f = test::sample_fractions(
      grid, [](const Vec3& x) { return x.x() < 4.5; }, 2, 4);
  AdaptOptions o = guaranteed_options();
  o.threshold = 0.9;
  const auto r = adapt(grid, f, majority_materials(f), o);
  EXPECT_TRUE(r.stopped_bad_input);
  ASSERT_FALSE(r.bad_input_cells.empty());
  for (CellId c : r.bad_input_cells) EXPECT_LT(grid.cell_quality(c), 0.9);
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) EXPECT_EQ(r.mesh.point(v), grid.point(v));
  o.allow_bad_input = true;
  const auto a = adapt(grid, f, majority_materials(f), o);
  EXPECT_FALSE(a.stopped_bad_input);
  // No cell below the threshold gets worse than the input's worst.
  EXPECT_GE(a.min_quality, min_quality(grid) - 1e-12);
}

TEST(GuaranteedMethod, GivesTheSameMeshWhateverTheThreadCount) {
  const QuadMesh grid = make_quad_grid(64, 40);
  const Fractions f = test::sample_fractions(
      grid,
      [](const Vec3& p) {
        return static_cast<int>(std::floor((p.x() + 2.0 * std::sin(0.3 * p.y())) / 4.1)) % 3;
      },
      3, 4);
  set_threads(1);
  const auto a = adapt(grid, f, majority_materials(f), guaranteed_options());
  set_threads(2);
  const auto b = adapt(grid, f, majority_materials(f), guaranteed_options());
  set_threads(0);
  ASSERT_EQ(a.mesh.n_nodes(), b.mesh.n_nodes());
  for (NodeId v : id_range<NodeId>(a.mesh.n_nodes())) ASSERT_EQ(a.mesh.point(v), b.mesh.point(v));
  EXPECT_EQ(a.blocked.raw(), b.blocked.raw());
  EXPECT_EQ(a.dist_final, b.dist_final);
}

TEST(GuaranteedMethod, RejectsBadOptions) {
  const QuadMesh grid = make_quad_grid(4, 4);
  const Fractions f = test::sample_fractions(
      grid, [](const Vec3& p) { return p.x() < 1.5; }, 2, 4);
  AdaptOptions o = guaranteed_options();
  o.max_loops = -1;
  EXPECT_THROW(adapt(grid, f, majority_materials(f), o), OptionError);
  o.max_loops = 3;
  o.loop_tolerance = -1;
  EXPECT_THROW(adapt(grid, f, majority_materials(f), o), OptionError);
}

}  // namespace
}  // namespace hexadapt
