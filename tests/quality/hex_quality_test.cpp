// Known answers for the hex scaled Jacobian and shape (Verdict definitions): a table of
// elements whose values follow from a short derivation given next to each row.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "hexadapt/quality/scaled_jacobian.h"
#include "hexadapt/quality/shape.h"

namespace hexadapt {
namespace {

using Hex = std::array<Vec3, 8>;

// The unit cube mapped through f, binary corner order.
Hex mapped_cube(const std::function<Vec3(const Vec3&)>& f) {
  Hex p;
  for (std::size_t v = 0; v < 8; ++v)
    p[v] = f(Vec3(double(v & 1u), double((v >> 1) & 1u), double((v >> 2) & 1u)));
  return p;
}

Hex unit_cube() {
  return mapped_cube([](const Vec3& x) { return x; });
}

// Corner 7 of the unit cube pulled out to (1 + t)(1, 1, 1). At corner 7 the (mirrored)
// edges are the rows of I + t J (J all ones): det 1 + 3t, each length sqrt((1+t)^2 + 2t^2).
// At corners 3, 5, 6 one edge becomes (t, t, 1 + t): det 1 + t. The other corners and the
// centre frame are better, so these two kinds give the minimum.
Hex pulled_corner(double t) {
  Hex p = unit_cube();
  p[7] = Vec3(1 + t, 1 + t, 1 + t);
  return p;
}
double pulled_corner_sj(double t) {
  const double l2 = (1 + t) * (1 + t) + 2 * t * t;
  return std::min((1 + 3 * t) / std::pow(l2, 1.5), (1 + t) / std::sqrt(l2));
}
double pulled_corner_shape(double t) {
  const double l2 = (1 + t) * (1 + t) + 2 * t * t;
  return std::min(std::cbrt((1 + 3 * t) * (1 + 3 * t)) / l2,
                  3 * std::cbrt((1 + t) * (1 + t)) / (2 + l2));
}

struct HexCase {
  std::string name;
  Hex points;
  double scaled_jacobian;
  double shape;
};

std::vector<HexCase> hex_cases() {
  const double s = 0.7;  // shear factor
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  return {
      {"unit cube", unit_cube(), 1.0, 1.0},
      {"scaled, rotated, translated cube",
       mapped_cube([&](const Vec3& x) { return Vec3(rot * (2.5 * x) + Vec3(-3, 7, 1e3)); }), 1.0,
       1.0},
      // A box a x b x c: right angles, so the scaled Jacobian is 1; shape = 3 (abc)^(2/3) /
      // (a^2 + b^2 + c^2).
      {"box 1 x 2 x 4",
       mapped_cube([](const Vec3& x) { return Vec3(x.x(), 2 * x.y(), 4 * x.z()); }), 1.0,
       3 * std::cbrt(64.0) / 21},
      // x += s y: every frame is (e1, e2 + s e1, e3): det 1, lengths 1, sqrt(1 + s^2), 1.
      {"sheared cube",
       mapped_cube([&](const Vec3& x) { return Vec3(x.x() + s * x.y(), x.y(), x.z()); }),
       1 / std::sqrt(1 + s * s), 3 / (3 + s * s)},
      {"mirrored (inverted) cube",
       mapped_cube([](const Vec3& x) { return Vec3(-x.x(), x.y(), x.z()); }), -1.0, 0.0},
      {"pulled corner t = 1", pulled_corner(1.0), pulled_corner_sj(1.0), pulled_corner_shape(1.0)},
      {"pulled corner t = 0.3", pulled_corner(0.3), pulled_corner_sj(0.3),
       pulled_corner_shape(0.3)},
      // Corner 7 pushed to the centre: its mirrored frame is -(rows of (J - I) / 2), with
      // det(J - I) = 2, so the corner value is -(2 / 8) / (3/4)^(3/2) = -4 / (3 sqrt 3).
      {"corner pushed to the centre",
       [] {
         Hex p = unit_cube();
         p[7] = Vec3(0.5, 0.5, 0.5);
         return p;
       }(),
       -4 / (3 * std::sqrt(3.0)), 0.0},
  };
}

TEST(HexQuality, KnownAnswers) {
  for (const auto& c : hex_cases()) {
    EXPECT_NEAR(hex_scaled_jacobian(c.points), c.scaled_jacobian, 1e-12) << c.name;
    EXPECT_NEAR(hex_shape(c.points), c.shape, 1e-12) << c.name;
  }
}

TEST(HexQuality, PulledCornerDerivationIsNotTrivial) {
  // The table rows above must exercise a value far from 1 and from each other.
  EXPECT_NEAR(pulled_corner_sj(1.0), 4 / std::pow(6.0, 1.5), 1e-15);
  EXPECT_LT(pulled_corner_sj(1.0), 0.3);
}

TEST(HexQuality, DegenerateCellsScoreTheWorst) {
  Hex collapsed_edge = unit_cube();
  collapsed_edge[1] = collapsed_edge[0];
  Hex flat = mapped_cube([](const Vec3& x) { return Vec3(x.x(), x.y(), 0); });
  Hex point = mapped_cube([](const Vec3&) { return Vec3(1, 2, 3); });
  Hex nan = unit_cube();
  nan[5].x() = std::nan("");
  for (const Hex& p : {collapsed_edge, flat, point, nan}) {
    EXPECT_EQ(hex_scaled_jacobian(p), -1.0);
    EXPECT_EQ(hex_shape(p), 0.0);
  }
}

TEST(HexQuality, IndependentOfUnits) {
  for (double scale : {1e-120, 1e-6, 1e6, 1e120}) {
    const Hex p = mapped_cube([&](const Vec3& x) {
      return Vec3(scale * (x.x() + 0.7 * x.y()), scale * x.y(), scale * x.z());
    });
    EXPECT_NEAR(hex_scaled_jacobian(p), 1 / std::sqrt(1.49), 1e-12) << scale;
    EXPECT_NEAR(hex_shape(p), 3 / 3.49, 1e-12) << scale;
  }
}

TEST(HexQuality, VolumeOfAShearedBox) {
  const Hex p =
      mapped_cube([](const Vec3& x) { return Vec3(2 * x.x() + x.y(), 3 * x.y(), x.z()); });
  EXPECT_NEAR(hex_volume(p), 6.0, 1e-12);
}

}  // namespace
}  // namespace hexadapt
