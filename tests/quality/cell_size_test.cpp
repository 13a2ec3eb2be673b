// Known answers for the size metrics: edge lengths, edge ratio and time-step length of
// boxes, a collapsed cell and an inverted one; the one-pass and bounded forms the
// adaptation's score uses against the whole computations.
#include "hexadapt/quality/cell_size.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "hexadapt/quality/scaled_jacobian.h"
#include "quality/box_cells.h"

namespace hexadapt {
namespace {

std::array<Vec3, 4> rectangle(double a, double b) {
  return {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, b, 0), Vec3(0, b, 0)};
}

TEST(CellSize, HexBoxEdgesAndTimeStep) {
  const EdgeLengths e = hex_edge_lengths(test::box_hex(1, 2, 4));
  EXPECT_DOUBLE_EQ(e.min, 1);
  EXPECT_DOUBLE_EQ(e.max, 4);
  EXPECT_DOUBLE_EQ(e.mean, 7.0 / 3.0);  // four edges of each length
  EXPECT_DOUBLE_EQ(e.ratio(), 4);
  // volume 8, largest face 2 x 4 = 8: the thinnest direction, 1.
  EXPECT_DOUBLE_EQ(hex_time_step_length(test::box_hex(1, 2, 4)), 1);
  EXPECT_DOUBLE_EQ(hex_time_step_length(test::box_hex(3, 3, 3)), 3);
}

TEST(CellSize, QuadRectangleEdgesAndTimeStep) {
  const EdgeLengths e = quad_edge_lengths(rectangle(2, 0.5));
  EXPECT_DOUBLE_EQ(e.min, 0.5);
  EXPECT_DOUBLE_EQ(e.max, 2);
  EXPECT_DOUBLE_EQ(e.mean, 1.25);
  EXPECT_DOUBLE_EQ(e.ratio(), 4);
  EXPECT_DOUBLE_EQ(quad_time_step_length(rectangle(2, 0.5)), 0.5);  // area 1 / edge 2
}

TEST(CellSize, ScalesWithTheUnit) {
  const double s = 1e-4;
  EXPECT_DOUBLE_EQ(hex_edge_lengths(test::box_hex(s, 2 * s, 4 * s)).ratio(), 4);
  EXPECT_NEAR(hex_time_step_length(test::box_hex(s, 2 * s, 4 * s)), s, 1e-15 * s);
  EXPECT_NEAR(quad_time_step_length(rectangle(2e6, 5e5)), 5e5, 1e-9);
}

// A quad whose edge 1-2 has collapsed to a point: the shortest edge is 0, the ratio infinite.
TEST(CellSize, CollapsedEdgeIsZeroNeverSmallAndFinite) {
  const std::array<Vec3, 4> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_EQ(quad_edge_lengths(p).min, 0);
  EXPECT_EQ(quad_edge_lengths(p).ratio(), std::numeric_limits<double>::infinity());
}

TEST(CellSize, InvertedOrNanCellsHaveNoTimeStep) {
  std::array<Vec3, 4> cw = rectangle(1, 1);
  std::swap(cw[1], cw[3]);
  EXPECT_EQ(quad_time_step_length(cw), 0);
  std::array<Vec3, 8> h = test::box_hex(1, 1, 1);
  h[7].x() = std::nan("");
  EXPECT_EQ(hex_time_step_length(h), 0);
  EXPECT_EQ(hex_edge_lengths(h).min, 0);
}

// Verdict's hex scaled Jacobian the plain way, each corner's three edges normalised on their
// own: the reference the one-pass computation is checked against.
double reference_scaled_jacobian(const std::array<Vec3, 8>& p) {
  double longest = 0;
  for (const auto& e : ref_hex::edges)
    longest = std::max(longest, (p[std::size_t(e[1])] - p[std::size_t(e[0])]).norm());
  if (!(longest > 0) || !std::isfinite(longest)) return -1;
  std::vector<std::array<Vec3, 3>> frames = {
      {(p[1] + p[3] + p[5] + p[7]) - (p[0] + p[2] + p[4] + p[6]),
       (p[2] + p[3] + p[6] + p[7]) - (p[0] + p[1] + p[4] + p[5]),
       (p[4] + p[5] + p[6] + p[7]) - (p[0] + p[1] + p[2] + p[3])}};
  for (std::size_t v = 0; v < 8; ++v) {
    const Vec3 a = p[v ^ 1u] - p[v], b = p[v ^ 2u] - p[v], c = p[v ^ 4u] - p[v];
    const bool odd = ((v & 1u) ^ ((v >> 1) & 1u) ^ ((v >> 2) & 1u)) != 0;
    frames.push_back(odd ? std::array<Vec3, 3>{b, a, c} : std::array<Vec3, 3>{a, b, c});
  }
  double worst = 1;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto& [a, b, c] = frames[k];
    const double tiny = 1e-13 * longest * (k == 0 ? 4 : 1);
    if (!(a.norm() > tiny && b.norm() > tiny && c.norm() > tiny)) return -1;
    const double j = (a / a.norm()).dot((b / b.norm()).cross(c / c.norm()));
    if (!std::isfinite(j)) return -1;
    worst = std::min(worst, j);
  }
  return std::clamp(worst, -1.0, 1.0);
}

// The one-pass metrics of the adaptation's cell score give the scaled Jacobian computed the
// plain way and the edge lengths, on boxes with corners jittered up to inversion, a collapsed
// edge and a NaN.
TEST(CellSize, ShapeAndSizeInOnePassAreTheTwoApart) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.6, 0.6);
  std::vector<std::array<Vec3, 8>> hexes;
  for (int k = 0; k < 200; ++k) {
    std::array<Vec3, 8> p = test::box_hex(1, 2, 0.5);
    for (Vec3& x : p) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    hexes.push_back(p);
  }
  hexes.push_back(test::box_hex(1, 1, 1));
  hexes.back()[3] = hexes.back()[1];
  hexes.push_back(test::box_hex(1, 1, 1));
  hexes.back()[6].z() = std::nan("");
  int inverted = 0;
  for (const auto& p : hexes) {
    const HexShapeAndSize m = hex_shape_and_size(p);
    const EdgeLengths e = hex_edge_lengths(p);
    EXPECT_EQ(m.scaled_jacobian, hex_scaled_jacobian(p));
    EXPECT_DOUBLE_EQ(m.scaled_jacobian, reference_scaled_jacobian(p));
    EXPECT_EQ(m.shortest_edge, e.min);
    inverted += m.scaled_jacobian < 0;
  }
  EXPECT_GT(inverted, 10);  // the sample reaches inverted cells, not only good ones
  EXPECT_EQ(hex_shape_and_size(hexes[200]).scaled_jacobian, -1);
  EXPECT_EQ(hex_shape_and_size(hexes[201]).shortest_edge, 0);
}

// What a cell can reach while one corner moves: over jittered boxes and quads, no position of
// that corner scores above the bound (nor gets a longer shortest edge than the edges away
// from it), and a cell whose worst corner is away from the moving one is at its bound.
template <std::size_t N>
void check_bounds(const std::vector<std::array<Vec3, N>>& cells,
                  double (*sj)(const std::array<Vec3, N>&),
                  ShapeAndSizeBound (*bound)(const std::array<Vec3, N>&, std::size_t),
                  EdgeLengths (*edges)(const std::array<Vec3, N>&)) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> step(-1.5, 1.5);
  int at_bound = 0;
  for (const auto& p : cells)
    for (std::size_t moving = 0; moving < N; ++moving) {
      const ShapeAndSizeBound b = bound(p, moving);
      at_bound += sj(p) == b.scaled_jacobian;
      for (int k = 0; k < 40; ++k) {
        std::array<Vec3, N> q = p;
        q[moving] += Vec3(step(rng), step(rng), N == 8 ? step(rng) : 0.0);
        EXPECT_LE(sj(q), b.scaled_jacobian);
        EXPECT_LE(edges(q).min, b.shortest_edge);
      }
    }
  EXPECT_GT(at_bound, static_cast<int>(cells.size()) / 2);  // the bound is often reached
}

TEST(CellSize, NoMoveOfOneCornerRaisesACellAboveItsBound) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  std::vector<std::array<Vec3, 8>> hexes;
  std::vector<std::array<Vec3, 4>> quads;
  for (int k = 0; k < 60; ++k) {
    hexes.push_back(test::box_hex(1, 2, 0.5));
    for (Vec3& x : hexes.back()) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    quads.push_back(rectangle(1, 2));
    for (Vec3& x : quads.back()) x += Vec3(jitter(rng), jitter(rng), 0);
  }
  check_bounds<8>(hexes, hex_scaled_jacobian, hex_bound_moving, hex_edge_lengths);
  check_bounds<4>(quads, quad_scaled_jacobian, quad_bound_moving, quad_edge_lengths);
  // A collapsed edge away from the moving corner caps the shortest edge at 0.
  std::array<Vec3, 8> flat = test::box_hex(1, 1, 1);
  flat[7] = flat[6];
  EXPECT_EQ(hex_bound_moving(flat, 0).shortest_edge, 0);
  EXPECT_EQ(hex_bound_moving(flat, 0).scaled_jacobian, 1);  // no direction there: no bound
}

// The figures a score needs down to a bound (hex_shape_and_size with min_edge and
// stop_below): bit for bit the whole computation where they are at or above their bounds,
// below the bound where the whole one is. The hexes include inversions, a collapsed edge and
// a NaN.
void expect_as_whole(const HexShapeAndSize& got, const std::array<Vec3, 8>& p, double min_edge,
                     double stop_below) {
  const double shortest = hex_edge_lengths(p).min, whole = hex_scaled_jacobian(p);
  EXPECT_EQ(got.shortest_edge, shortest);
  if (shortest < min_edge) {
    EXPECT_EQ(got.scaled_jacobian, -1);
  } else if (whole >= stop_below) {
    EXPECT_EQ(got.scaled_jacobian, whole);
  } else {
    EXPECT_LT(got.scaled_jacobian, stop_below);
  }
}

TEST(CellSize, ScoresDownToABoundAreTheWholeComputationAboveIt) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4), step(-1.2, 1.2), bound(-1.2, 1.0);
  int stopped = 0, exact = 0;
  for (int k = 0; k < 80; ++k) {
    std::array<Vec3, 8> p = test::box_hex(1, 2, 0.5);
    for (Vec3& x : p) x += Vec3(jitter(rng), jitter(rng), jitter(rng));
    for (std::size_t moving = 0; moving < 8; ++moving) {
      for (int t = 0; t < 12; ++t) {
        std::array<Vec3, 8> q = p;
        q[moving] += Vec3(step(rng), step(rng), step(rng));
        if (t == 10) q[moving] = p[moving ^ 1u];  // a collapsed edge
        if (t == 11) q[moving].y() = std::nan("");
        const double min_edge = t % 3 == 0 ? 0.0 : 0.3, stop_below = bound(rng);
        expect_as_whole(hex_shape_and_size(q, min_edge, stop_below), q, min_edge, stop_below);
        const double whole = hex_scaled_jacobian(q);
        stopped +=
            whole < stop_below && hex_shape_and_size(q, 0, stop_below).scaled_jacobian != whole;
        exact += whole >= stop_below;
      }
    }
  }
  EXPECT_GT(stopped, 100);  // the bound does stop computations early
  EXPECT_GT(exact, 1000);
}

}  // namespace
}  // namespace hexadapt
