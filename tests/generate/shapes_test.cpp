#include "hexadapt/generate/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>

namespace hexadapt::generate {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

std::mt19937_64 rng(12345);

Vec3 random_point(std::uint64_t, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return Vec3(u(rng), u(rng), u(rng));
}

Vec3 random_direction(std::uint64_t) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 d(u(rng), u(rng), u(rng));
  return d.norm() > 1e-3 ? d.normalized() : Vec3::UnitX();
}

// The distance bound is conservative: moving less than it never changes the side.
void expect_conservative(const Primitive& shape) {
  int tested = 0;
  for (std::uint64_t i = 0; i < 4000; ++i) {
    const Vec3 p = random_point(i, -0.2, 1.2);
    const double d = shape.boundary_distance(p);
    if (!(d > 0) || !std::isfinite(d)) continue;
    ++tested;
    for (double t : {0.3, 0.7, 0.999}) {
      const Vec3 q = p + t * d * random_direction(i);
      ASSERT_EQ(shape.contains(q), shape.contains(p)) << "p " << p.transpose() << " d " << d;
    }
  }
  EXPECT_GT(tested, 1000);
}

TEST(Shapes, BallClassifiesAndBoundsDistance) {
  const Ball b(Vec3(0.5, 0.5, 0.5), 0.3);
  EXPECT_TRUE(b.contains(Vec3(0.5, 0.5, 0.79)));
  EXPECT_FALSE(b.contains(Vec3(0.5, 0.5, 0.81)));
  EXPECT_NEAR(b.boundary_distance(Vec3(0.5, 0.5, 0.5)), 0.3, 1e-15);
  expect_conservative(b);
}

TEST(Shapes, BoxIsHalfOpenAndConservative) {
  const Box b(Vec3(0.2, 0.3, -inf), Vec3(0.6, inf, inf));
  EXPECT_TRUE(b.contains(Vec3(0.2, 0.3, 0)));
  EXPECT_FALSE(b.contains(Vec3(0.6, 0.5, 0)));
  EXPECT_DOUBLE_EQ(b.boundary_distance(Vec3(0.3, 0.9, 5)), 0.1);
  expect_conservative(b);
  expect_conservative(Box(Vec3(0.1, 0.2, 0.3), Vec3(0.7, 0.8, 0.9)));
}

TEST(Shapes, WavyGraphIsConservativeIn2DAnd3D) {
  const BelowGraph g2(2, 0.5, 0.1, 2.0, 0.3), g3(3, 0.5, 0.1, 2.0, 0.3);
  EXPECT_TRUE(g2.contains(Vec3(0.1, g2.height(Vec3(0.1, 0, 0)) - 1e-9, 0)));
  EXPECT_FALSE(g3.contains(Vec3(0.1, 0.2, g3.height(Vec3(0.1, 0.2, 0)) + 1e-9)));
  expect_conservative(g2);
  expect_conservative(g3);
}

TEST(Shapes, NoisyBallIsSeededAndConservative) {
  const NoisyBall a(Vec3(0.5, 0.5, 0.5), 0.3, 0.15, 1), b(Vec3(0.5, 0.5, 0.5), 0.3, 0.15, 1),
      c(Vec3(0.5, 0.5, 0.5), 0.3, 0.15, 2);
  const Vec3 p(0.9, 0.6, 0.4);
  EXPECT_EQ(a.surface_radius(p), b.surface_radius(p));
  EXPECT_NE(a.surface_radius(p), c.surface_radius(p));
  for (std::uint64_t i = 0; i < 200; ++i) {
    const double r = a.surface_radius(random_point(i, 0, 1));
    EXPECT_GE(r, 0.3 * 0.85);
    EXPECT_LE(r, 0.3 * 1.15);
  }
  expect_conservative(a);
}

TEST(Shapes, LayoutPaintsInOrder) {
  Layout l(0);
  l.paint(1, std::make_shared<Ball>(Vec3(0, 0, 0), 1.0));
  l.paint(2, std::make_shared<Ball>(Vec3(1, 0, 0), 1.0));
  EXPECT_EQ(l.material_at(Vec3(-0.5, 0, 0)), 1);
  EXPECT_EQ(l.material_at(Vec3(0.5, 0, 0)), 2);  // the later paint wins
  EXPECT_EQ(l.material_at(Vec3(5, 0, 0)), 0);
  EXPECT_EQ(l.max_material(), 2);
  EXPECT_NEAR(l.clearance(Vec3(-0.5, 0, 0)), 0.5, 1e-15);
}

}  // namespace
}  // namespace hexadapt::generate
