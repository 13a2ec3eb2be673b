// Clipping a convex polyhedron by one half-space: each face is clipped as a polygon and the
// points on the plane, which bound a convex polygon, are ordered by angle to form the cap.
#include <algorithm>
#include <array>
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

void tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Polyhedron& out) {
  out.clear();
  for (const auto& f :
       {std::array<const Vec3*, 3>{&a, &c, &b}, std::array<const Vec3*, 3>{&a, &b, &d},
        std::array<const Vec3*, 3>{&a, &d, &c}, std::array<const Vec3*, 3>{&b, &c, &d}}) {
    for (const Vec3* q : f) out.points.push_back(*q);
    out.close_face();
  }
}

double polyhedron_volume(const Polyhedron& p) {
  if (p.points.empty()) return 0;
  const Vec3 r = p.points.front();
  double v = 0;
  for (std::size_t f = 0; f < p.n_faces(); ++f) {
    const std::size_t b = p.begin(f), e = p.end[f];
    for (std::size_t i = b + 1; i + 1 < e; ++i)
      v += tet_volume(r, p.points[b], p.points[i], p.points[i + 1]);
  }
  return v;
}

namespace {

// A value in [0, 4) increasing with the angle of (x, y), like atan2 but without its cost.
double pseudo_angle(double x, double y) {
  const double l1 = std::abs(x) + std::abs(y);
  if (l1 == 0) return 0;
  const double p = y / l1;  // in [-1, 1]
  return x >= 0 ? (y >= 0 ? p : 4 + p) : 2 - p;
}

// Orders points [first, end) of a convex planar polygon counter-clockwise around n.
void order_cap(std::vector<Vec3>& pts, std::size_t first, const Vec3& n) {
  const std::size_t m = pts.size() - first;
  Vec3 c = Vec3::Zero();
  for (std::size_t i = first; i < pts.size(); ++i) c += pts[i];
  c /= static_cast<double>(m);
  const Vec3 u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 v = n.cross(u);
  thread_local std::vector<std::pair<double, Vec3>> keyed;
  keyed.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 d = pts[first + i] - c;
    keyed[i] = {pseudo_angle(d.dot(u), d.dot(v)), pts[first + i]};
  }
  std::sort(keyed.begin(), keyed.begin() + static_cast<std::ptrdiff_t>(m),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t i = 0; i < m; ++i) pts[first + i] = keyed[i].second;
}

}  // namespace

void clip_polyhedron(Polyhedron& p, const Plane& plane, Polyhedron& out) {
  // Sides within rounding of the plane are snapped to it, so that a face lying in the plane
  // is recognised as such (else it would be kept in part and covered again by the cap).
  double scale = 0;
  for (const Vec3& a : p.points) scale = std::max(scale, std::abs(plane.side(a)));
  const double snap = 1e-13 * scale;
  auto side = [&](const Vec3& a) {
    const double s = plane.side(a);
    return std::abs(s) <= snap ? 0.0 : s;
  };
  bool any_in = false, any_out = false;
  for (const Vec3& a : p.points) {
    const double s = side(a);
    any_in = any_in || s < 0;
    any_out = any_out || s > 0;
  }
  if (!any_out) return;
  if (!any_in) {
    p.clear();
    return;
  }
  out.clear();
  // The cap's points are gathered at the end of `cap` (a second buffer in out.points would
  // interleave with the faces), then appended as the last face.
  thread_local std::vector<Vec3> cap;
  cap.clear();
  for (std::size_t f = 0; f < p.n_faces(); ++f) {
    const std::size_t b = p.begin(f), e = p.end[f], n = e - b, start = out.points.size();
    bool in_plane = true;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& a = p.points[b + i];
      const Vec3& c = p.points[b + (i + 1) % n];
      const double sa = side(a), sc = side(c);
      in_plane = in_plane && sa == 0;
      if (sa <= 0) out.points.push_back(a);
      if (sa == 0) cap.push_back(a);
      if ((sa < 0 && sc > 0) || (sa > 0 && sc < 0)) {
        const Vec3 q = a + (sa / (sa - sc)) * (c - a);
        out.points.push_back(q);
        cap.push_back(q);
      }
    }
    // A face in the plane is part of the cap, which is built below.
    if (out.points.size() - start >= 3 && !in_plane)
      out.close_face();
    else
      out.points.resize(start);
  }
  if (cap.size() >= 3) {
    const std::size_t first = out.points.size();
    out.points.insert(out.points.end(), cap.begin(), cap.end());
    order_cap(out.points, first, plane.n);
    out.close_face();
  }
  std::swap(p, out);
}

}  // namespace hexadapt::clip
