#include "hexadapt/generate/flows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "hexadapt/core/error.h"

namespace hexadapt::generate {
namespace {

constexpr double pi = 3.141592653589793;

double divergence(const Flow& f, const Vec3& p, double t, int dim) {
  const double h = 1e-5;
  double div = 0;
  for (int a = 0; a < dim; ++a) {
    Vec3 e = Vec3::Zero();
    e[a] = h;
    div += (f.velocity(p + e, t)[a] - f.velocity(p - e, t)[a]) / (2 * h);
  }
  return div;
}

void expect_divergence_free(const Flow& f, int dim) {
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < (dim == 3 ? 7 : 1); ++k) {
        const Vec3 p(0.07 + 0.13 * i, 0.11 + 0.12 * j, dim == 3 ? 0.09 + 0.13 * k : 0.0);
        const double scale = 1 + f.velocity(p, 0.3).norm();
        EXPECT_NEAR(divergence(f, p, 0.3, dim), 0.0, 1e-7 * scale) << p.transpose();
      }
}

TEST(Flows, AllAreDivergenceFree) {
  expect_divergence_free(SingleVortex(8), 2);
  expect_divergence_free(Deformation3D(3), 3);
  expect_divergence_free(CompactVortex(Vec3(0.5, 0.4, 0), 0.4, -3), 2);
  expect_divergence_free(DropFlow(2, Vec3(0.5, 0.45, 0), 0.4, 0.8), 2);
  expect_divergence_free(DropFlow(3, Vec3(0.5, 0.5, 0.45), 0.4, 0.8), 3);
}

TEST(Flows, DropFlowGoesDownTheAxis) {
  const DropFlow f(3, Vec3(0.5, 0.5, 0.4), 0.4, 0.8);
  EXPECT_NEAR(f.velocity(Vec3(0.5, 0.5, 0.4), 0).z(), -0.8, 1e-15);
  EXPECT_GT(f.velocity(Vec3(0.75, 0.5, 0.4), 0).z(), 0.0);  // and up the sides
  EXPECT_EQ(f.velocity(Vec3(0.5, 0.5, 0.81), 0), Vec3::Zero());
}

// A compact vortex rotates each circle by omega(r) t: RK4 must reproduce the exact map.
TEST(Flows, TraceBackMatchesTheExactVortexRotation) {
  const Vec3 c(1, 1.5, 0);
  const double radius = 1, omega = -2 * pi, t = 1;
  const CompactVortex f(c, radius, omega);
  for (double r : {0.1, 0.35, 0.6, 0.9}) {
    const Vec3 p = c + Vec3(r * std::cos(0.3), r * std::sin(0.3), 0);
    const double s = 1 - r * r;
    const double angle = -omega * s * s * s * t;  // backwards in time
    const Vec3 exact = c + Vec3(r * std::cos(0.3 + angle), r * std::sin(0.3 + angle), 0);
    EXPECT_NEAR((trace_back(f, p, t, automatic_steps(f, t)) - exact).norm(), 0.0, 1e-4) << r;
    EXPECT_NEAR((trace_back(f, p, t, 400) - exact).norm(), 0.0, 1e-9) << r;
  }
}

TEST(Flows, ReversedFlowsReturnAfterAPeriod) {
  const SingleVortex f(2);
  const Vec3 p(0.5, 0.75, 0);
  EXPECT_NEAR((trace_back(f, p, 2.0, 400) - p).norm(), 0.0, 1e-9);
  EXPECT_GT((trace_back(f, p, 1.0, 400) - p).norm(), 0.1);
}

TEST(Flows, StillOutsideTheSupport) {
  const CompactVortex v(Vec3(0, 0, 0), 1, 5);
  EXPECT_TRUE(v.still_in(Vec3(2, 0, 0), 0.5));
  EXPECT_FALSE(v.still_in(Vec3(2, 0, 0), 1.5));
  EXPECT_EQ(trace_back(v, Vec3(1.2, 0.3, 0), 3, 10), Vec3(1.2, 0.3, 0));
  const SumFlow both({std::make_shared<CompactVortex>(Vec3(0, 0, 0), 1, 5),
                      std::make_shared<CompactVortex>(Vec3(3, 0, 0), 1, -5)});
  EXPECT_FALSE(both.still_in(Vec3(3, 0, 0), 0.1));
  EXPECT_TRUE(both.still_in(Vec3(1.5, 5, 0), 0.1));
  EXPECT_FALSE(SingleVortex(8).still_in(Vec3(0.5, 0.5, 0), 0.01));
}

TEST(Flows, AbsurdOrNonFiniteTimesAreRefusedNotCast) {
  const SingleVortex f(8);
  EXPECT_GE(automatic_steps(f, 8), 1);
  for (const double t : {1e9, -1e9, 1e300, std::nan(""), HUGE_VAL, -HUGE_VAL})
    EXPECT_THROW(automatic_steps(f, t), OptionError) << t;
}

}  // namespace
}  // namespace hexadapt::generate
