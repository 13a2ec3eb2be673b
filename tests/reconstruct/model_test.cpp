#include "hexadapt/reconstruct/model.h"

#include <gtest/gtest.h>

#include "hexadapt/core/parallel.h"
#include "hexadapt/reconstruct/reconstruct.h"
#include "reconstruct/cases.h"

namespace hexadapt::reconstruct {
namespace {

// Volume of material m in the pixel mesh plus the cells without pixels.
template <class M>
double pixel_volume(const M& mesh, const PixelMesh& px, const CellMaterials& assign, int m) {
  double v = 0;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const index_t b = px.cell_block(c);
    if (b < 0) {
      if (assign[c] == m) v += mesh.cell_volume(c);
      continue;
    }
    for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p)
      if (px.label(p) == m) v += px.volume(p);
  }
  return v;
}

template <class M>
void expect_closed_inner_material(const testcase::Case<M>& c, Method method) {
  ReconstructOptions o;
  o.method = method;
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, o);
  ASSERT_FALSE(r.model.facets.empty());
  EXPECT_EQ(open_boundary_count(r.model, 1), 0);
  const double want = pixel_volume(c.mesh, r.pixels, c.majority, 1);
  EXPECT_NEAR(enclosed_volume(r.model, 1), want, 1e-9 * want);
  for (const auto& m : r.model.facet_materials) EXPECT_LT(m[0], m[1]);
}

TEST(Model, DiskIsClosedAndEnclosesItsPixels) {
  expect_closed_inner_material(
      testcase::make_case(make_quad_grid(8, 8), 2, testcase::disk(4, 4, 2.3)), Method::greedy);
}

TEST(Model, JitteredDiskIsClosedAndEnclosesItsPixels) {
  expect_closed_inner_material(
      testcase::make_case(testcase::jittered_grid(8, 8, 0.3), 2, testcase::disk(4.1, 3.9, 2.3)),
      Method::annealing);
}

TEST(Model, SphereIsClosedAndEnclosesItsPixels) {
  expect_closed_inner_material(testcase::sphere(6, 2.2), Method::greedy);
}

TEST(Model, PureCellInterfacesAreIncluded) {
  // A 2x2 block of material 1 in pure material 0 cells: no mixed cell, no pixels at all.
  auto c = testcase::make_case(make_quad_grid(4, 4), 2, [](const Vec3& p) {
    return p.x() > 1 && p.x() < 3 && p.y() > 1 && p.y() < 3 ? 1 : 0;
  });
  ReconstructOptions o;
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, o);
  EXPECT_EQ(r.pixels.n_blocks(), 0);
  EXPECT_EQ(r.model.facets.size(), 8u * 10u);
  EXPECT_EQ(open_boundary_count(r.model, 1), 0);
  EXPECT_NEAR(enclosed_volume(r.model, 1), 4.0, 1e-12);
  EXPECT_TRUE(r.model.corners.empty());
}

TEST(Model, TriplePointsAndBoundaryEndsAreCorners) {
  const auto c = testcase::five_by_five();
  ReconstructOptions o;
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, o);
  int triple = 0, boundary = 0;
  for (index_t v : r.model.corners) {
    const Vec3& p = r.model.points[static_cast<std::size_t>(v)];
    const bool on_boundary =
        p.x() < 1e-12 || p.y() < 1e-12 || p.x() > 5 - 1e-12 || p.y() > 5 - 1e-12;
    (on_boundary ? boundary : triple) += 1;
  }
  EXPECT_GE(triple, 1);
  EXPECT_GE(boundary, 2);
}

TEST(Model, SameModelWhateverTheThreadCount) {
  const auto c = testcase::sphere(6, 2.2);
  ReconstructOptions o;
  set_threads(1);
  const auto a = reconstruct(c.mesh, c.fractions, c.majority, o);
  set_threads(2);
  const auto b = reconstruct(c.mesh, c.fractions, c.majority, o);
  set_threads(0);
  EXPECT_EQ(a.model.facets, b.model.facets);
  EXPECT_EQ(a.model.points, b.model.points);
  EXPECT_EQ(a.result.edgecut, b.result.edgecut);
  EXPECT_EQ(a.result.discrepancy, b.result.discrepancy);
}

TEST(Model, SphereHasNoFeatureCurves) {
  const auto c = testcase::sphere(6, 2.2);
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, ReconstructOptions{});
  // Two materials away from the boundary: only checkerboard edges may be features.
  for (const auto& e : r.model.curves) {
    const Vec3& p = r.model.points[static_cast<std::size_t>(e[0])];
    EXPECT_GT(p.minCoeff(), 0);
  }
}

}  // namespace
}  // namespace hexadapt::reconstruct
