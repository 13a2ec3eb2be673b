#include "hexadapt/quality/scaled_jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "frames.h"

namespace hexadapt {

namespace {

// det(a, b, c) / (|a| |b| |c|) computed on unit vectors, so that neither tiny nor huge
// coordinates underflow or overflow the product of the lengths. False for a degenerate frame.
bool scaled_det(const Vec3& a, const Vec3& b, const Vec3& c, double scale, double& out) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double tiny = quality_detail::degenerate_length * scale;
  if (!(la > tiny && lb > tiny && lc > tiny)) return false;  // also catches NaN
  out = (a / la).dot((b / lb).cross(c / lc));
  return std::isfinite(out);
}

// Corner V's Jacobian from the unit edges (hex_corner_frame): its edges along x, y, z
// pointing away from V, x and y swapped at the corners of odd parity. V is known at compile
// time: the score's hot loop is unrolled, with no branch on V's bits.
template <std::size_t V>
[[gnu::always_inline]] inline double corner_jacobian(const std::array<Vec3, 12>& unit) {
  const auto edge = [&](int axis) -> Vec3 {
    const Vec3& u = unit[quality_detail::hex_edge_index(V, axis)];
    return (V >> axis) & 1u ? Vec3(-u) : u;
  };
  constexpr unsigned parity = (V & 1u) ^ ((V >> 1) & 1u) ^ ((V >> 2) & 1u);
  if constexpr (parity != 0) return edge(1).dot(edge(0).cross(edge(2)));
  return edge(0).dot(edge(1).cross(edge(2)));
}

// The same for a corner known at run time (the bounds).
double corner_jacobian(const std::array<Vec3, 12>& unit, std::size_t v) {
  using Corner = double (*)(const std::array<Vec3, 12>&);
  static constexpr std::array<Corner, 8> corners = {
      &corner_jacobian<0>, &corner_jacobian<1>, &corner_jacobian<2>, &corner_jacobian<3>,
      &corner_jacobian<4>, &corner_jacobian<5>, &corner_jacobian<6>, &corner_jacobian<7>};
  return corners[v](unit);
}

// The least corner Jacobian, corner by corner, stopping at the first one that makes it
// non-finite (false) or below stop_below.
template <std::size_t... V>
[[gnu::always_inline]] inline bool least_corner(const std::array<Vec3, 12>& unit, double stop_below,
                                                double& worst, std::index_sequence<V...>) {
  bool finite = true;
  const auto take = [&](double j) {
    if (!std::isfinite(j)) {
      finite = false;
      return true;
    }
    worst = std::min(worst, j);
    return worst < stop_below;
  };
  (take(corner_jacobian<V>(unit)) || ...);
  return finite;
}

// The unit vector of edge k of p; false when the edge has no direction.
bool unit_edge(const quality_detail::HexEdges& e, std::size_t k, Vec3& out) {
  if (!(e.length[k] > 0) || !std::isfinite(e.length[k])) return false;
  out = e.vec[k] / e.length[k];
  return true;
}

// A quad corner's Jacobian: the cross product of its two edges made unit.
double unit_cross(const Eigen::Vector2d& a, double la, const Eigen::Vector2d& b, double lb) {
  const Eigen::Vector2d ua = a / la, ub = b / lb;
  return ua.x() * ub.y() - ua.y() * ub.x();
}

}  // namespace

double quality_detail::hex_scaled_jacobian(const std::array<Vec3, 8>& p,
                                           const quality_detail::HexEdges& e, double stop_below) {
  const double scale = e.longest;
  if (!(scale > 0) || !std::isfinite(scale)) return -1.0;
  // Every edge is in some corner frame, so one collapsed edge makes the cell degenerate.
  const double tiny = quality_detail::degenerate_length * scale;
  std::array<Vec3, 12> unit;
  for (std::size_t k = 0; k < 12; ++k) {
    if (!(e.length[k] > tiny)) return -1.0;  // also catches NaN
    unit[k] = e.vec[k] / e.length[k];
  }
  // The corners before the centre: a corner is mostly the worst, so a cell below stop_below
  // is mostly known after a few corners. Clamping keeps an early value below stop_below, or
  // makes it -1, which the whole minimum then is too.
  double worst = 1.0;
  if (!least_corner(unit, stop_below, worst, std::make_index_sequence<8>{})) return -1.0;
  if (worst < stop_below) return std::clamp(worst, -1.0, 1.0);
  const auto axes = quality_detail::hex_principal_axes(p);
  double centre;
  if (!scaled_det(axes[0], axes[1], axes[2], 4 * scale, centre)) return -1.0;
  return std::clamp(std::min(worst, centre), -1.0, 1.0);
}

double hex_scaled_jacobian(const std::array<Vec3, 8>& p) {
  return quality_detail::hex_scaled_jacobian(p, quality_detail::hex_edges(p),
                                             -std::numeric_limits<double>::infinity());
}

double quality_detail::hex_scaled_jacobian_bound(const quality_detail::HexEdges& e,
                                                 std::size_t moving) {
  double bound = 1.0;
  std::array<Vec3, 12> unit;
  for (std::size_t v = 0; v < 8; ++v) {
    const std::size_t d = v ^ moving;
    if (d == 0 || (d & (d - 1)) == 0) continue;  // v's frame holds the moving corner
    for (int axis = 0; axis < 3; ++axis) {
      const std::size_t k = quality_detail::hex_edge_index(v, axis);
      if (!unit_edge(e, k, unit[k])) return 1.0;
    }
    const double j = corner_jacobian(unit, v);
    if (std::isfinite(j)) bound = std::min(bound, j);
  }
  return std::max(bound, -1.0);
}

double hex_volume(const std::array<Vec3, 8>& p) {
  const double g = 0.5 / std::sqrt(3.0);
  double vol = 0;
  for (int q = 0; q < 8; ++q) {
    const double s[3] = {0.5 + ((q & 1) ? g : -g), 0.5 + ((q & 2) ? g : -g),
                         0.5 + ((q & 4) ? g : -g)};
    Vec3 d[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (std::size_t v = 0; v < 8; ++v) {
      for (int axis = 0; axis < 3; ++axis) {
        // d/ds_axis of the trilinear shape function of node v.
        double w = ((v >> axis) & 1u) ? 1.0 : -1.0;
        for (int o = 0; o < 3; ++o) {
          if (o == axis) continue;
          w *= ((v >> o) & 1u) ? s[o] : 1.0 - s[o];
        }
        d[axis] += w * p[v];
      }
    }
    vol += d[0].dot(d[1].cross(d[2])) / 8.0;
  }
  return vol;
}

double quad_scaled_jacobian(const std::array<Vec3, 4>& p) {
  const double scale = quality_detail::quad_scale(p);
  if (!(scale > 0) || !std::isfinite(scale)) return -1.0;
  const double tiny = quality_detail::degenerate_length * scale;
  double worst = 1.0;
  for (std::size_t v = 0; v < 4; ++v) {
    const auto [a, b] = quality_detail::quad_corner_frame(p, v);
    const double la = a.norm(), lb = b.norm();
    if (!(la > tiny && lb > tiny)) return -1.0;
    worst = std::min(worst, unit_cross(a, la, b, lb));
  }
  return std::clamp(worst, -1.0, 1.0);
}

double quality_detail::quad_scaled_jacobian_bound(const std::array<Vec3, 4>& p,
                                                  std::size_t moving) {
  const auto [a, b] = quality_detail::quad_corner_frame(p, (moving + 2) % 4);
  const double la = a.norm(), lb = b.norm();
  if (!(la > 0 && lb > 0) || !std::isfinite(la) || !std::isfinite(lb)) return 1.0;
  const double j = unit_cross(a, la, b, lb);
  return std::isfinite(j) ? std::clamp(j, -1.0, 1.0) : 1.0;
}

double quad_area(const std::array<Vec3, 4>& p) {
  return 0.5 * ((p[2].x() - p[0].x()) * (p[3].y() - p[1].y()) -
                (p[3].x() - p[1].x()) * (p[2].y() - p[0].y()));
}

}  // namespace hexadapt
