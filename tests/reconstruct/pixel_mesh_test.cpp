#include "hexadapt/reconstruct/pixel_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "hexadapt/core/error.h"
#include "reconstruct/cases.h"

namespace hexadapt::reconstruct {
namespace {

// Every pixel's neighbour across a face has exactly one face pointing back, and the two
// centres are about a pixel width apart.
void expect_symmetric_neighbours(const PixelMesh& px) {
  for (std::int64_t p = 0; p < px.n_pixels(); ++p)
    for (int lf = 0; lf < px.faces_per_pixel(); ++lf) {
      const std::int64_t q = px.neighbour(p, lf);
      if (q < 0) continue;
      int back = 0;
      for (int lg = 0; lg < px.faces_per_pixel(); ++lg) back += px.neighbour(q, lg) == p;
      ASSERT_EQ(back, 1) << "pixel " << p << " face " << lf;
      EXPECT_LT((px.centre(p) - px.centre(q)).norm(), 1.6 * px.mean_width());
    }
}

TEST(PixelMesh, PixelatesMixedCellsAndTheirNodeNeighbours) {
  const auto c = testcase::make_case(make_quad_grid(8, 8), 2, testcase::disk(4, 4, 2.2));
  const PixelMesh px = build_pixel_mesh(c.mesh, c.fractions, c.majority, {});
  EXPECT_EQ(px.nsub(), 10);
  for (CellId cell : id_range<CellId>(c.mesh.n_cells())) {
    bool near_mixed = false;
    for (NodeId n : c.mesh.cell_nodes(cell))
      for (CellId o : c.mesh.node_cells(n)) near_mixed |= !c.fractions.is_pure(o);
    const index_t b = px.cell_block(cell);
    ASSERT_EQ(b >= 0, near_mixed) << "cell " << cell.value();
    if (b < 0) continue;
    EXPECT_EQ(px.block_free(b), !c.fractions.is_pure(cell));
    double vol = 0;
    for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p) {
      vol += px.volume(p);
      EXPECT_EQ(px.label(p), px.block_free(b) ? PixelMesh::unassigned : c.majority[cell]);
    }
    EXPECT_NEAR(vol, c.mesh.cell_volume(cell), 1e-12);
  }
  expect_symmetric_neighbours(px);
}

TEST(PixelMesh, JitteredCellsHavePixelsOfDifferentVolumes) {
  const auto c =
      testcase::make_case(testcase::jittered_grid(6, 6, 0.3), 2, testcase::disk(3, 3, 1.7));
  const PixelMesh px = build_pixel_mesh(c.mesh, c.fractions, c.majority, {});
  double lo = 1e300, hi = 0;
  for (std::int64_t p = 0; p < px.n_pixels(); ++p) {
    lo = std::min(lo, px.volume(p));
    hi = std::max(hi, px.volume(p));
  }
  EXPECT_GT(hi / lo, 1.2);
  for (index_t b = 0; b < px.n_blocks(); ++b) {
    double vol = 0;
    for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p) vol += px.volume(p);
    EXPECT_NEAR(vol, c.mesh.cell_volume(px.block_cell(b)), 1e-12);
  }
  expect_symmetric_neighbours(px);
}

TEST(PixelMesh, LinksCellsWhoseLatticesAreRotated) {
  // Two hexes side by side along x; the second one's nodes are listed rotated a quarter
  // turn about x, so its lattice axes differ from the first one's.
  HexMesh grid = make_hex_grid(2, 1, 1);
  std::vector<HexMesh::CellNodes> cells{grid.cell_nodes(CellId(0)), grid.cell_nodes(CellId(1))};
  const auto old = cells[1];
  for (int v = 0; v < 8; ++v) {
    const int i = v & 1, j = (v >> 1) & 1, k = (v >> 2) & 1;
    const int src = i + 2 * (1 - k) + 4 * j;  // rotation (i, j, k) -> (i, 1 - k, j)
    cells[1][static_cast<std::size_t>(v)] = old[static_cast<std::size_t>(src)];
  }
  HexMesh mesh(grid.points(), cells);
  ASSERT_GT(mesh.cell_volume(CellId(1)), 0);
  Fractions f(2, {"a", "b"});
  f(CellId(0), 0) = 0.5;
  f(CellId(0), 1) = 0.5;
  f(CellId(1), 0) = 1;
  PixelOptions o;
  o.nsub = 3;
  const PixelMesh px = build_pixel_mesh(mesh, f, CellMaterials(2, 0), o);
  ASSERT_EQ(px.n_blocks(), 2);
  expect_symmetric_neighbours(px);
  // Centres across the shared face x = 1 are one pixel width apart along x.
  int crossing = 0;
  for (std::int64_t p = 0; p < px.pixels_per_block(); ++p)
    for (int lf = 0; lf < 6; ++lf) {
      const std::int64_t q = px.neighbour(p, lf);
      if (q < px.pixels_per_block()) continue;
      ++crossing;
      EXPECT_NEAR((px.centre(q) - px.centre(p)).x(), 1.0 / 3, 1e-12);
      EXPECT_NEAR((px.centre(q) - px.centre(p)).y(), 0, 1e-12);
      EXPECT_NEAR((px.centre(q) - px.centre(p)).z(), 0, 1e-12);
    }
  EXPECT_EQ(crossing, 9);
}

TEST(PixelMesh, RefusesBeyondTheMemoryLimitBeforeAllocating) {
  const auto c = testcase::sphere(6, 2.2);
  PixelOptions o;
  o.max_memory = 1e4;
  EXPECT_THROW(build_pixel_mesh(c.mesh, c.fractions, c.majority, o), ResourceError);
  const PixelPlan plan = plan_pixels(c.mesh, c.fractions, c.majority, {});
  EXPECT_EQ(plan.nsub, 4);
  EXPECT_EQ(plan.n_pixels, 64 * plan.n_blocks);
  EXPECT_GT(plan.bytes, 12.0 * static_cast<double>(plan.n_pixels));
}

TEST(PixelMesh, CellSharesOfTheEstimateAddUpToThePlan) {
  const auto c = testcase::sphere(10, 2.2);
  PixelOptions o;
  o.method_bytes_per_free_pixel = 40;
  o.output_bytes_per_pixel = 100;
  const PixelPlan plan = plan_pixels(c.mesh, c.fractions, c.majority, o);
  const auto whole = dist::Block::whole(c.mesh.n_cells(), c.mesh.n_nodes());
  const std::vector<double> shares = owned_cell_bytes(c.mesh, c.fractions, c.majority, o, whole);
  ASSERT_EQ(shares.size(), static_cast<std::size_t>(c.mesh.n_cells()));
  double sum = 0;
  for (double b : shares) sum += b;
  EXPECT_NEAR(sum, plan.bytes, 1e-9 * plan.bytes);
  // A plain cell, a pixelated pure one, a mixed one: 4 bytes, then its pixels, then the method's.
  std::vector<double> kinds(shares);
  std::sort(kinds.begin(), kinds.end());
  kinds.erase(std::unique(kinds.begin(), kinds.end()), kinds.end());
  ASSERT_EQ(kinds.size(), 3u);
  EXPECT_EQ(kinds[0], 4.0);
  EXPECT_EQ(kinds[2] - kinds[1], 40.0 * 64);
  // A part: the shares of the cells it owns.
  dist::Block part = whole;
  part.owned_cell_first = 10;
  part.owned_cell_end = 30;
  EXPECT_EQ(owned_cell_bytes(c.mesh, c.fractions, c.majority, o, part),
            std::vector<double>(shares.begin() + 10, shares.begin() + 30));
}

TEST(PixelMesh, RejectsBadAssignments) {
  const auto c = testcase::make_case(make_quad_grid(3, 3), 2, testcase::disk(1.5, 1.5, 1));
  auto bad = c.majority;
  bad[CellId(4)] = 7;
  EXPECT_THROW(build_pixel_mesh(c.mesh, c.fractions, bad, {}), InputError);
  bad.resize(bad.size() - 1);
  EXPECT_THROW(build_pixel_mesh(c.mesh, c.fractions, bad, {}), InputError);
  PixelOptions o;
  o.nsub = 0 - 1;
  EXPECT_THROW(build_pixel_mesh(c.mesh, c.fractions, c.majority, o), OptionError);
}

}  // namespace
}  // namespace hexadapt::reconstruct
