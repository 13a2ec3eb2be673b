// Clipping a convex polyhedron by one half-space: each face is clipped as a polygon and the
// points on the plane, which bound a convex polygon, are ordered by angle to form the cap.
#include <algorithm>
#include <cmath>
#include <utility>

#include "clip.h"

namespace hexadapt::clip {

Plane plane_through(const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 n = (b - a).cross(c - a);
  const double len = n.norm();
  if (len > 0) n /= len;
  // Offset from the mean of the three points: the same plane whichever corner comes first.
  return {n, n.dot((a + b + c) / 3.0)};
}

double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

Polyhedron tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return {{{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}}};
}

double polyhedron_volume(const Polyhedron& p) {
  if (p.faces.empty()) return 0;
  const Vec3 r = p.faces.front().front();
  double v = 0;
  for (const Polygon& f : p.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) v += tet_volume(r, f[0], f[i], f[i + 1]);
  return v;
}

namespace {

// Orders points of a convex planar polygon counter-clockwise around the normal n.
void order_cap(Polygon& cap, const Vec3& n) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& q : cap) c += q;
  c /= static_cast<double>(cap.size());
  const Vec3 u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 v = n.cross(u);
  std::vector<std::pair<double, Vec3>> keyed;
  keyed.reserve(cap.size());
  for (const Vec3& q : cap) keyed.emplace_back(std::atan2((q - c).dot(v), (q - c).dot(u)), q);
  std::sort(keyed.begin(), keyed.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t i = 0; i < cap.size(); ++i) cap[i] = keyed[i].second;
}

}  // namespace

void clip_polyhedron(Polyhedron& p, const Plane& plane) {
  // Sides within rounding of the plane are snapped to it, so that a face lying in the plane
  // is recognised as such (else it would be kept in part and covered again by the cap).
  double scale = 0;
  for (const Polygon& f : p.faces)
    for (const Vec3& a : f) scale = std::max(scale, std::abs(plane.side(a)));
  const double snap = 1e-13 * scale;
  auto side = [&](const Vec3& a) {
    const double s = plane.side(a);
    return std::abs(s) <= snap ? 0.0 : s;
  };
  bool any_in = false, any_out = false;
  for (const Polygon& f : p.faces)
    for (const Vec3& a : f) {
      const double s = side(a);
      any_in = any_in || s < 0;
      any_out = any_out || s > 0;
    }
  if (!any_out) return;
  if (!any_in) {
    p.faces.clear();
    return;
  }
  Polyhedron out;
  Polygon cap, clipped;
  for (const Polygon& f : p.faces) {
    clipped.clear();
    bool in_plane = true;
    const std::size_t n = f.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& a = f[i];
      const Vec3& b = f[(i + 1) % n];
      const double sa = side(a), sb = side(b);
      in_plane = in_plane && sa == 0;
      if (sa <= 0) clipped.push_back(a);
      if (sa == 0) cap.push_back(a);
      if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
        const Vec3 q = a + (sa / (sa - sb)) * (b - a);
        clipped.push_back(q);
        cap.push_back(q);
      }
    }
    // A face in the plane is part of the cap, which is built below.
    if (clipped.size() >= 3 && !in_plane) out.faces.push_back(clipped);
  }
  if (cap.size() >= 3) {
    order_cap(cap, plane.n);
    out.faces.push_back(cap);
  }
  p = std::move(out);
}

}  // namespace hexadapt::clip
