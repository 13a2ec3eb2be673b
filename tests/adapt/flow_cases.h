// Triple-point-like and stir-like material layouts for the pipeline tests: analytic regions
// rolled up by a swirl, so the fractions have the thin, curved features of an advection
// code's output (the generator of hexadapt-generate produces the real cases).
#pragma once

#include <cmath>

#include "adapt/adapt_cases.h"

namespace hexadapt::test {

/// The point that a swirl of strength `turns` (radians at the centre, Gaussian of width
/// `width`) around `centre` carried to p, traced back.
inline Vec3 unswirl(const Vec3& p, const Vec3& centre, double turns, double width) {
  const Vec3 d = p - centre;
  const double r2 = d.x() * d.x() + d.y() * d.y();
  const double a = -turns * std::exp(-r2 / (width * width));
  return centre + Vec3(std::cos(a) * d.x() - std::sin(a) * d.y(),
                       std::sin(a) * d.x() + std::cos(a) * d.y(), d.z());
}

/// Three materials on [0,7]x[0,3] meeting at (1, 1.5), swirled around the triple point.
inline Shape triple_point(double turns) {
  return [turns](const Vec3& p) {
    const Vec3 q = unswirl(p, Vec3(1.0, 1.5, p.z()), turns, 0.9);
    if (q.x() < 1.0) return 0;
    return q.y() < 1.5 ? 1 : 2;
  };
}

/// A disk in the unit square stirred into a spiral arm.
inline Shape stirred_disk(double turns) {
  return [turns](const Vec3& p) {
    const Vec3 q = unswirl(p, Vec3(0.5, 0.5, p.z()), turns, 0.3);
    Vec3 d = q - Vec3(0.5, 0.72, q.z());
    d.z() = 0;
    return d.norm() < 0.16 ? 1 : 0;
  };
}

}  // namespace hexadapt::test
