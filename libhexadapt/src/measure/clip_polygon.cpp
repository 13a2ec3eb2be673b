// Sutherland-Hodgman clipping of a polygon by one half-plane.
#include "clip.h"

namespace hexadapt::clip {

double polygon_area(const Polygon& p) {
  double a = 0;
  const std::size_t n = p.size();
  if (n < 3) return 0;
  // Relative to the first vertex: keeps rounding proportional to the polygon's size.
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec3 u = p[i] - p[0], v = p[i + 1] - p[0];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return 0.5 * a;
}

void clip_polygon(const Polygon& p, const Plane& plane, Polygon& out) {
  out.clear();
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % n];
    const double sa = plane.side(a), sb = plane.side(b);
    if (sa <= 0) out.push_back(a);
    if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) out.push_back(a + (sa / (sa - sb)) * (b - a));
  }
}

}  // namespace hexadapt::clip
