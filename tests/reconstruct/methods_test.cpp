// The four assignment methods on small cases with known properties.
#include <gtest/gtest.h>

#include <iostream>

#include "hexadapt/core/parallel.h"
#include "hexadapt/reconstruct/reconstruct.h"
#include "mesh/scaled_mesh.h"
#include "reconstruct/cases.h"

namespace hexadapt::reconstruct {
namespace {

template <class M>
PixelMesh pixels_of(const testcase::Case<M>& c, int nsub = 0) {
  PixelOptions o;
  o.nsub = nsub;
  return build_pixel_mesh(c.mesh, c.fractions, c.majority, o);
}

// Every free pixel carries a material of its own cell.
void expect_valid_labels(const PixelMesh& px, const Fractions& f) {
  for (std::int64_t p = 0; p < px.n_pixels(); ++p) {
    ASSERT_GE(px.label(p), 0);
    if (px.pixel_free(p)) {
      EXPECT_GT(f(px.block_cell(px.pixel_block(p)), px.label(p)), 0);
    }
  }
}

TEST(Greedy, KeepsCellVolumesWithinOnePixel2D) {
  const auto c = testcase::five_by_five();
  PixelMesh px = pixels_of(c);
  greedy_assign(px, c.fractions);
  expect_valid_labels(px, c.fractions);
  EXPECT_LE(testcase::worst_gap_in_pixels(px, c.fractions), 1.0 + 1e-9);
}

TEST(Greedy, KeepsCellVolumesWithinOnePixel3D) {
  const auto c = testcase::sphere(6, 2.2);
  PixelMesh px = pixels_of(c);
  greedy_assign(px, c.fractions);
  expect_valid_labels(px, c.fractions);
  EXPECT_LE(testcase::worst_gap_in_pixels(px, c.fractions), 1.0 + 1e-9);
}

TEST(Greedy, BeatsRandomFillOnEdgecut) {
  const auto c = testcase::five_by_five();
  PixelMesh greedy = pixels_of(c), random = pixels_of(c);
  greedy_assign(greedy, c.fractions);
  largest_remainder_fill(random, c.fractions, 3);
  EXPECT_LT(edgecut(greedy), edgecut(random) / 2);
}

TEST(Annealing, KeepsCountsAndLowersEdgecut) {
  const auto c = testcase::five_by_five();
  PixelMesh px = pixels_of(c);
  AnnealingOptions o;
  o.seed = 5;
  const auto r = annealing_assign(px, c.fractions, o);
  expect_valid_labels(px, c.fractions);
  EXPECT_LE(testcase::worst_gap_in_pixels(px, c.fractions), 1.0 + 1e-9);
  EXPECT_GT(r.accepted, 0);
  EXPECT_LT(edgecut(px), r.initial_edgecut * 2 / 3);
  EXPECT_LT(r.final_energy, r.initial_energy);
}

TEST(Annealing, SameSeedSameResultWhateverTheThreadCount) {
  const auto c = testcase::five_by_five();
  AnnealingOptions o;
  o.iterations = 20000;
  o.seed = 9;
  set_threads(1);
  PixelMesh a = pixels_of(c);
  annealing_assign(a, c.fractions, o);
  set_threads(2);
  PixelMesh b = pixels_of(c);
  annealing_assign(b, c.fractions, o);
  EXPECT_EQ(a.labels(), b.labels());
  o.seed = 10;
  PixelMesh d = pixels_of(c);
  annealing_assign(d, c.fractions, o);
  EXPECT_NE(a.labels(), d.labels());
  set_threads(0);
}

TEST(Greedy, SameResultWhateverTheThreadCount) {
  const auto c = testcase::sphere(6, 2.2);
  set_threads(1);
  PixelMesh a = pixels_of(c);
  greedy_assign(a, c.fractions);
  set_threads(2);
  PixelMesh b = pixels_of(c);
  greedy_assign(b, c.fractions);
  set_threads(0);
  EXPECT_EQ(a.labels(), b.labels());
}

// The same pixels, model and relative discrepancy in any unit and place: the greedy compares
// volumes inside one cell only, in units of the cell's first pixel, and the stage runs in
// the grid's UnitFrame (at 1e-300 pixel areas underflow, at 1e300 volumes overflow).
template <class M>
void expect_the_same_in_any_unit(const testcase::Case<M>& c) {
  const CellMaterials& assignment = c.majority;
  const Reconstruction r = reconstruct(c.mesh, c.fractions, assignment, {});
  for (auto [scale, offset] :
       {std::pair{1e-300, 0.0}, {1e-6, 0.0}, {1e6, 0.0}, {1e300, 0.0}, {1.0, 1e6}}) {
    const Reconstruction s =
        reconstruct(test::scaled(c.mesh, scale, offset), c.fractions, assignment, {});
    EXPECT_EQ(s.pixels.labels(), r.pixels.labels()) << scale << " " << offset;
    EXPECT_NEAR(s.result.relative_discrepancy, r.result.relative_discrepancy, 1e-12) << scale;
    ASSERT_EQ(s.model.points.size(), r.model.points.size()) << scale << " " << offset;
    const Vec3 moved =
        scale * r.model.points.back() + Vec3(offset, offset, M::dim == 3 ? offset : 0);
    EXPECT_LT((s.model.points.back() - moved).cwiseAbs().maxCoeff(), 1e-9 * scale + 1e-6 * offset);
  }
}

TEST(Greedy, TheSameInAnyUnitAndPlace2D) {
  expect_the_same_in_any_unit(testcase::five_by_five());
}
TEST(Greedy, TheSameInAnyUnitAndPlace3D) {
  expect_the_same_in_any_unit(testcase::sphere(6, 2.2));
}

// Pure 0 | mixed 50/50 | pure 1: the best assignment of the middle cell is a straight
// split with material 0 on the left.
testcase::Case<QuadMesh> split_case() {
  return testcase::make_case(make_quad_grid(3, 1), 2,
                             [](const Vec3& p) { return p.x() < 1.5 ? 0 : 1; });
}

void expect_left_right_split(const PixelMesh& px) {
  const index_t b = px.cell_block(CellId(1));
  for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p)
    EXPECT_EQ(px.label(p), px.lattice(p)[0] < px.nsub() / 2 ? 0 : 1) << "pixel " << p;
}

TEST(Mip, SolvesASmallCaseToOptimality) {
  const auto c = split_case();
  PixelMesh px = pixels_of(c, 4);
  MipOptions o;
  o.time_limit = 20;
  const auto r = mip_assign(px, c.fractions, o);
  EXPECT_EQ(r.status, MipStatus::optimal);
  EXPECT_GT(r.n_variables, 0);
  expect_left_right_split(px);
  EXPECT_NEAR(r.best_bound, r.objective, 1e-9);
}

TEST(Mip, FiveByFiveMeetsTheCountsAndReportsItsStatus) {
  const auto c = testcase::five_by_five();
  PixelMesh px = pixels_of(c, 6);
  MipOptions o;
  o.time_limit = 2;
  const auto r = mip_assign(px, c.fractions, o);
  std::cout << "MIP 5x5 (nsub 6, 2 s): " << to_string(r.status) << ", objective " << r.objective
            << ", bound " << r.best_bound << ", " << r.seconds << " s\n";
  EXPECT_NE(r.status, MipStatus::no_free_pixels);
  EXPECT_LE(r.seconds, o.time_limit + 2);
  if (r.status == MipStatus::optimal) {
    EXPECT_NEAR(r.best_bound, r.objective, 1e-6);
  }
  if (r.status == MipStatus::feasible) {
    EXPECT_LE(r.best_bound, r.objective + 1e-9);
  }
  expect_valid_labels(px, c.fractions);
  // Counts are the largest-remainder ones exactly, whatever the status.
  for (index_t b = 0; b < px.n_blocks(); ++b) {
    if (!px.block_free(b)) continue;
    const auto want = largest_remainder_counts(px, c.fractions, b);
    std::vector<int> got(3, 0);
    for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p)
      ++got[static_cast<std::size_t>(px.label(p))];
    EXPECT_EQ(got, want);
  }
}

TEST(GraphCut, SplitsTheSmallCaseStraight) {
  const auto c = split_case();
  PixelMesh px = pixels_of(c, 4);
  const auto r = graph_cut_assign(px, c.fractions);
  expect_left_right_split(px);
  EXPECT_LE(r.final_energy, r.initial_energy);
}

TEST(GraphCut, LowersItsEnergyAndUsesCellMaterialsOnly) {
  const auto c = testcase::five_by_five();
  PixelMesh px = pixels_of(c);
  GraphCutOptions o;
  o.lambda = 0.2;
  const auto r = graph_cut_assign(px, c.fractions, o);
  expect_valid_labels(px, c.fractions);
  EXPECT_LE(r.final_energy, r.initial_energy);
  EXPECT_GE(r.cycles, 1);
}

// The paper's Fig. 8 finding: on unstructured cells annealing matches pixel counts, not
// volumes, so its discrepancy is higher than the greedy method's.
TEST(Methods, JitteredGridDiscrepancy) {
  const auto c =
      testcase::make_case(testcase::jittered_grid(8, 8, 0.3), 2, testcase::disk(4.1, 3.9, 2.3));
  PixelMesh g = pixels_of(c), a = pixels_of(c), gc = pixels_of(c), lr = pixels_of(c);
  greedy_assign(g, c.fractions);
  annealing_assign(a, c.fractions);
  graph_cut_assign(gc, c.fractions);
  const double dg = discrepancy(g, c.fractions), da = discrepancy(a, c.fractions);
  std::cout << "jittered 8x8 disk, nsub 10: discrepancy greedy " << dg << ", annealing " << da
            << ", graphcut " << discrepancy(gc, c.fractions) << "; edgecut greedy " << edgecut(g)
            << ", annealing " << edgecut(a) << ", graphcut " << edgecut(gc) << "\n";
  EXPECT_LT(dg, da);
}

}  // namespace
}  // namespace hexadapt::reconstruct
