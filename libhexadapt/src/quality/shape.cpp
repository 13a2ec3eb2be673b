#include "hexadapt/quality/shape.h"

#include <algorithm>
#include <cmath>

#include "frames.h"

namespace hexadapt {

double hex_shape(const std::array<Vec3, 8>& p) {
  const double scale = quality_detail::hex_scale(p);
  if (!(scale > 0) || !std::isfinite(scale)) return 0.0;
  double worst = 1.0;
  for (std::size_t v = 0; v < 8; ++v) {
    auto f = quality_detail::hex_corner_frame(p, v);
    // The metric is scale-invariant: work in units of the longest edge to stay in range.
    for (auto& e : f) e /= scale;
    const double det = f[0].dot(f[1].cross(f[2]));
    const double norm2 = f[0].squaredNorm() + f[1].squaredNorm() + f[2].squaredNorm();
    if (!(det > 0) || !(norm2 > 0)) return 0.0;
    worst = std::min(worst, 3.0 * std::cbrt(det * det) / norm2);
  }
  return std::clamp(worst, 0.0, 1.0);
}

double quad_shape(const std::array<Vec3, 4>& p) {
  const double scale = quality_detail::quad_scale(p);
  if (!(scale > 0) || !std::isfinite(scale)) return 0.0;
  const double tiny = quality_detail::degenerate_length;
  double worst = 1.0;
  for (std::size_t v = 0; v < 4; ++v) {
    auto [a, b] = quality_detail::quad_corner_frame(p, v);
    a /= scale;
    b /= scale;
    if (!(a.norm() > tiny && b.norm() > tiny)) return 0.0;
    worst = std::min(worst,
                     2.0 * (a.x() * b.y() - a.y() * b.x()) / (a.squaredNorm() + b.squaredNorm()));
  }
  return std::clamp(worst, 0.0, 1.0);
}

}  // namespace hexadapt
