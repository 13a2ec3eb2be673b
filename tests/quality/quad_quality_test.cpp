// Known answers for the quad scaled Jacobian (signed, +z) and shape: a table of elements
// whose values follow from a short derivation given next to each row.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hexadapt/quality/scaled_jacobian.h"
#include "hexadapt/quality/shape.h"

namespace hexadapt {
namespace {

using Quad = std::array<Vec3, 4>;

Quad quad(double x0, double y0, double x1, double y1, double x2, double y2, double x3, double y3) {
  return {Vec3(x0, y0, 0), Vec3(x1, y1, 0), Vec3(x2, y2, 0), Vec3(x3, y3, 0)};
}

// The unit square with corner 2 moved to (t, t). At corner 2 the edges are (-t, 1 - t) and
// (1 - t, -t): cross = 2t - 1, lengths^2 = t^2 + (1 - t)^2 = l2. At corners 1 and 3 one edge
// becomes (t - 1, t) (length sqrt(l2)) and the cross is t.
Quad kite(double t) {
  return quad(0, 0, 1, 0, t, t, 0, 1);
}
double kite_sj(double t) {
  const double l2 = t * t + (1 - t) * (1 - t);
  return std::min({1.0, (2 * t - 1) / l2, t / std::sqrt(l2)});
}
double kite_shape(double t) {
  const double l2 = t * t + (1 - t) * (1 - t);
  return std::max(0.0, std::min({1.0, (2 * t - 1) / l2, 2 * t / (1 + l2)}));
}

struct QuadCase {
  std::string name;
  Quad points;
  double scaled_jacobian;
  double shape;
};

std::vector<QuadCase> quad_cases() {
  const double c = std::cos(0.4), s = std::sin(0.4), k = 3.0;
  auto rotated = [&](double x, double y) {
    return Vec3(k * (c * x - s * y) + 5, k * (s * x + c * y) - 2, 0);
  };
  const double sh = 0.5;
  return {
      {"unit square", quad(0, 0, 1, 0, 1, 1, 0, 1), 1.0, 1.0},
      {"scaled, rotated, translated square",
       {rotated(0, 0), rotated(1, 0), rotated(1, 1), rotated(0, 1)},
       1.0,
       1.0},
      // Rectangle a x b: right angles; shape = 2ab / (a^2 + b^2).
      {"rectangle 1 x 3", quad(0, 0, 1, 0, 1, 3, 0, 3), 1.0, 6.0 / 10.0},
      // Parallelogram x += s y: corners see (1, 0) and (s, 1) (or their negatives): cross 1.
      {"sheared square", quad(0, 0, 1, 0, 1 + sh, 1, sh, 1), 1 / std::sqrt(1 + sh * sh),
       2 / (2 + sh * sh)},
      {"clockwise (inverted) square", quad(0, 0, 0, 1, 1, 1, 1, 0), -1.0, 0.0},
      {"convex kite t = 2", kite(2.0), 0.6, kite_shape(2.0)},
      // t < 1/2: corner 2 is reflex, the area stays positive.
      {"non-convex kite t = 0.25", kite(0.25), -0.8, 0.0},
      {"kite t = 0.8", kite(0.8), kite_sj(0.8), kite_shape(0.8)},
  };
}

TEST(QuadQuality, KnownAnswers) {
  for (const auto& q : quad_cases()) {
    EXPECT_NEAR(quad_scaled_jacobian(q.points), q.scaled_jacobian, 1e-12) << q.name;
    EXPECT_NEAR(quad_shape(q.points), q.shape, 1e-12) << q.name;
  }
  EXPECT_NEAR(kite_sj(2.0), 0.6, 1e-15);
  EXPECT_NEAR(kite_sj(0.25), -0.8, 1e-15);
}

TEST(QuadQuality, DegenerateCellsScoreTheWorst) {
  const Quad repeated = quad(0, 0, 1, 0, 1, 0, 0, 1);
  const Quad segment = quad(0, 0, 1, 0, 2, 0, 3, 0);  // all corners on a line: cross 0
  const Quad point = quad(1, 1, 1, 1, 1, 1, 1, 1);
  EXPECT_EQ(quad_scaled_jacobian(repeated), -1.0);
  EXPECT_EQ(quad_shape(repeated), 0.0);
  EXPECT_EQ(quad_scaled_jacobian(point), -1.0);
  EXPECT_EQ(quad_shape(point), 0.0);
  EXPECT_LE(quad_scaled_jacobian(segment), 0.0);
  EXPECT_EQ(quad_shape(segment), 0.0);
  Quad nan = quad(0, 0, 1, 0, 1, 1, 0, 1);
  nan[2].y() = std::nan("");
  EXPECT_EQ(quad_scaled_jacobian(nan), -1.0);
  EXPECT_EQ(quad_shape(nan), 0.0);
}

TEST(QuadQuality, AreaIsSigned) {
  EXPECT_NEAR(quad_area(quad(0, 0, 2, 0, 2, 3, 0, 3)), 6.0, 1e-15);
  EXPECT_NEAR(quad_area(quad(0, 0, 0, 3, 2, 3, 2, 0)), -6.0, 1e-15);
}

}  // namespace
}  // namespace hexadapt
