// The guarantee's score of one cell (quality/cell_score.h): the scaled Jacobian where the
// shortest edge is long enough, below every Jacobian where it is not, and bounds that no move
// of one corner beats.
#include "hexadapt/quality/cell_score.h"

#include <gtest/gtest.h>

#include <random>

#include "hexadapt/quality/cell_size.h"
#include "hexadapt/quality/scaled_jacobian.h"
#include "quality/box_cells.h"

namespace hexadapt {
namespace {

TEST(CellScore, TheJacobianWhereTheShortestEdgeIsLongEnough) {
  std::array<Vec3, 8> hex = test::box_hex(1, 2, 4);
  hex[7] += Vec3(0.3, -0.2, 0.1);
  const double sj = hex_scaled_jacobian(hex);
  EXPECT_EQ(hex_score(hex, 0), sj);    // size criterion off
  EXPECT_EQ(hex_score(hex, 0.9), sj);  // shortest edge 1 >= 0.9
  const std::array<Vec3, 4> quad = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2.2, 1, 0), Vec3(0, 1, 0)};
  EXPECT_EQ(quad_score(quad, 0), quad_scaled_jacobian(quad));
  EXPECT_EQ(quad_score(quad, 0.5), quad_scaled_jacobian(quad));
}

TEST(CellScore, BelowEveryJacobianWhereTheShortestEdgeIsTooShort) {
  const std::array<Vec3, 8> hex = test::box_hex(1, 2, 4);  // a perfect shape: Jacobian 1
  EXPECT_DOUBLE_EQ(hex_score(hex, 1.25), -2.0 + 1.0 / 1.25);
  const std::array<Vec3, 4> quad = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0.5, 0), Vec3(0, 0.5, 0)};
  EXPECT_DOUBLE_EQ(quad_score(quad, 1), -2.0 + 0.5);
  // An inverted cell with long edges still scores above a perfect sliver.
  std::array<Vec3, 8> inverted = test::box_hex(1, 1, 1);
  std::swap(inverted[0], inverted[1]);
  EXPECT_GT(hex_score(inverted, 0.5), hex_score(test::box_hex(1, 1, 0.1), 0.5));
  EXPECT_EQ(score_of(0.7, 0.2, 0.1), 0.7);
  EXPECT_DOUBLE_EQ(score_of(0.7, 0.05, 0.1), -1.5);
}

TEST(CellScore, ExactDownToTheBoundItIsAskedFor) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  for (int trial = 0; trial < 500; ++trial) {
    std::array<Vec3, 8> hex = test::box_hex(1, 1, 1);
    for (Vec3& q : hex) q += Vec3(jitter(rng), jitter(rng), jitter(rng));
    const double whole = hex_score(hex, 0.3);
    for (double stop : {-0.5, 0.0, 0.3, 0.6}) {
      const double got = hex_score(hex, 0.3, stop);
      if (whole >= stop)
        EXPECT_EQ(got, whole);
      else
        EXPECT_LT(got, stop);
    }
  }
}

TEST(CellScore, NoMoveOfOneCornerBeatsItsBound) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), far(-1.5, 1.5);
  for (int trial = 0; trial < 200; ++trial) {
    std::array<Vec3, 8> hex = test::box_hex(1, 1, 1);
    for (Vec3& q : hex) q += Vec3(jitter(rng), jitter(rng), jitter(rng));
    const std::size_t moving = static_cast<std::size_t>(trial % 8);
    const double bound = hex_score_bound(hex, moving, 0.4);
    for (int k = 0; k < 20; ++k) {
      std::array<Vec3, 8> moved = hex;
      moved[moving] += Vec3(far(rng), far(rng), far(rng));
      EXPECT_LE(hex_score(moved, 0.4), bound);
    }
    std::array<Vec3, 4> quad = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    for (Vec3& q : quad) q += Vec3(jitter(rng), jitter(rng), 0);
    const std::size_t corner = moving % 4;
    const double quad_bound = quad_score_bound(quad, corner, 0.4);
    for (int k = 0; k < 20; ++k) {
      std::array<Vec3, 4> moved = quad;
      moved[corner] += Vec3(far(rng), far(rng), 0);
      EXPECT_LE(quad_score(moved, 0.4), quad_bound);
    }
  }
}

}  // namespace
}  // namespace hexadapt
