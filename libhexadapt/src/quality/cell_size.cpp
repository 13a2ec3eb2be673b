#include "hexadapt/quality/cell_size.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frames.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

namespace {

using quality_detail::reported_shortest;

template <std::size_t E>
EdgeLengths edge_lengths(const std::array<double, E>& lengths) {
  EdgeLengths out;
  out.min = std::numeric_limits<double>::infinity();
  for (double len : lengths) {
    if (!std::isfinite(len)) return EdgeLengths{};
    out.min = std::min(out.min, len);
    out.max = std::max(out.max, len);
    out.mean += len;
  }
  out.mean /= static_cast<double>(E);
  out.min = reported_shortest(out.min, out.max);
  return out;
}

}  // namespace

double EdgeLengths::ratio() const {
  return min > 0 ? max / min : std::numeric_limits<double>::infinity();
}

EdgeLengths hex_edge_lengths(const std::array<Vec3, 8>& p) {
  return edge_lengths(quality_detail::hex_edges(p).length);
}

HexShapeAndSize hex_shape_and_size(const std::array<Vec3, 8>& p, double min_edge,
                                   double stop_below) {
  const quality_detail::HexEdges e = quality_detail::hex_edges(p);
  // edge_lengths(e.length).min without the mean, and with the longest hex_edges found.
  HexShapeAndSize out;
  out.shortest_edge = std::numeric_limits<double>::infinity();
  for (double len : e.length) {
    if (!std::isfinite(len)) return {-1.0, 0.0};
    out.shortest_edge = std::min(out.shortest_edge, len);
  }
  out.shortest_edge = reported_shortest(out.shortest_edge, e.longest);
  if (!(out.shortest_edge < min_edge))
    out.scaled_jacobian = quality_detail::hex_scaled_jacobian(p, e, stop_below);
  return out;
}

namespace {

// Whether hex edge k has corner v as one of its ends.
bool edge_touches(std::size_t k, std::size_t v) {
  const auto& ends = ref_hex::edges[k];
  return static_cast<std::size_t>(ends[0]) == v || static_cast<std::size_t>(ends[1]) == v;
}

// Whether corner v's frame holds corner `moving` (v itself or one of its three neighbours).
bool frame_holds(std::size_t v, std::size_t moving) {
  const std::size_t d = v ^ moving;
  return (d & (d - 1)) == 0;
}

}  // namespace

HexCornerMove::HexCornerMove(const std::array<Vec3, 8>& p, std::size_t moving)
    : p_(p), moving_(moving) {
  shortest_ = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 12; ++k) {
    if (edge_touches(k, moving)) continue;
    const auto& ends = ref_hex::edges[k];
    const Vec3 vec = p[static_cast<std::size_t>(ends[1])] - p[static_cast<std::size_t>(ends[0])];
    const double length = vec.norm();
    finite_ = finite_ && std::isfinite(length);
    shortest_ = std::min(shortest_, length);
    longest_ = std::max(longest_, length);
    unit_[k] = vec / length;  // used only where the edge is long enough
  }
  for (std::size_t v = 0; v < 8; ++v)
    if (!frame_holds(v, moving)) {
      const double j = quality_detail::corner_jacobian(unit_, v);
      corners_ = std::isfinite(corners_) && std::isfinite(j)
                     ? std::min(corners_, j)
                     : std::numeric_limits<double>::quiet_NaN();  // stays not finite
    }
}

// hex_shape_and_size and hex_scaled_jacobian step by step, with the parts away from the
// moving corner taken from the constructor: the same operations on the same values.
HexShapeAndSize HexCornerMove::at(const Vec3& corner, double min_edge, double stop_below) const {
  std::array<Vec3, 8> p = p_;
  p[moving_] = corner;
  std::array<Vec3, 12> unit = unit_;
  double shortest = shortest_, longest = longest_;
  bool finite = finite_;
  std::array<double, 3> length;
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t k = quality_detail::hex_edge_index(moving_, axis);
    const auto& ends = ref_hex::edges[k];
    unit[k] = p[static_cast<std::size_t>(ends[1])] - p[static_cast<std::size_t>(ends[0])];
    length[axis] = unit[k].norm();
    finite = finite && std::isfinite(length[axis]);
    shortest = std::min(shortest, length[axis]);
    longest = std::max(longest, length[axis]);
  }
  if (!finite) return {-1.0, 0.0};
  HexShapeAndSize out;
  out.shortest_edge = reported_shortest(shortest, longest);
  if (out.shortest_edge < min_edge) return out;
  const double tiny = quality_detail::degenerate_length * longest;
  if (!(longest > 0) || !std::isfinite(longest) || !(shortest > tiny)) return out;
  for (int axis = 0; axis < 3; ++axis)
    unit[quality_detail::hex_edge_index(moving_, axis)] /= length[axis];
  if (!std::isfinite(corners_)) return out;
  double worst = std::min(1.0, corners_);
  if (worst < stop_below) {
    out.scaled_jacobian = std::clamp(worst, -1.0, 1.0);
    return out;
  }
  // The moving corner first: after a move, mostly the worst.
  for (std::size_t bit : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{4}}) {
    const double j = quality_detail::corner_jacobian(unit, moving_ ^ bit);
    if (!std::isfinite(j)) return out;
    worst = std::min(worst, j);
    if (worst < stop_below) {
      out.scaled_jacobian = std::clamp(worst, -1.0, 1.0);
      return out;
    }
  }
  const auto axes = quality_detail::hex_principal_axes(p);
  double centre;
  if (quality_detail::scaled_det(axes[0], axes[1], axes[2], 4 * longest, centre))
    out.scaled_jacobian = std::clamp(std::min(worst, centre), -1.0, 1.0);
  return out;
}

ShapeAndSizeBound hex_bound_moving(const std::array<Vec3, 8>& p, std::size_t moving) {
  const quality_detail::HexEdges e = quality_detail::hex_edges(p);
  ShapeAndSizeBound b{quality_detail::hex_scaled_jacobian_bound(e, moving),
                      std::numeric_limits<double>::infinity()};
  for (std::size_t k = 0; k < 12; ++k) {
    const auto& ends = ref_hex::edges[k];
    if (static_cast<std::size_t>(ends[0]) != moving && static_cast<std::size_t>(ends[1]) != moving)
      b.shortest_edge = std::min(b.shortest_edge, e.length[k]);
  }
  return b;
}

ShapeAndSizeBound quad_bound_moving(const std::array<Vec3, 4>& p, std::size_t moving) {
  const std::size_t v = (moving + 1) % 4, w = (moving + 2) % 4, x = (moving + 3) % 4;
  return {quality_detail::quad_scaled_jacobian_bound(p, moving),
          std::min((p[w] - p[v]).norm(), (p[x] - p[w]).norm())};
}

EdgeLengths quad_edge_lengths(const std::array<Vec3, 4>& p) {
  std::array<double, 4> lengths;
  for (std::size_t v = 0; v < 4; ++v) lengths[v] = (p[(v + 1) % 4] - p[v]).norm();
  return edge_lengths(lengths);
}

double hex_time_step_length(const std::array<Vec3, 8>& p) {
  const double volume = hex_volume(p);
  double largest = 0;
  for (const auto& f : ref_hex::face_nodes) {
    const Vec3 d1 = p[static_cast<std::size_t>(f[2])] - p[static_cast<std::size_t>(f[0])];
    const Vec3 d2 = p[static_cast<std::size_t>(f[3])] - p[static_cast<std::size_t>(f[1])];
    largest = std::max(largest, 0.5 * d1.cross(d2).norm());
  }
  return volume > 0 && largest > 0 && std::isfinite(volume) ? volume / largest : 0.0;
}

double quad_time_step_length(const std::array<Vec3, 4>& p) {
  const double area = quad_area(p);
  const double longest = quad_edge_lengths(p).max;
  return area > 0 && longest > 0 && std::isfinite(area) ? area / longest : 0.0;
}

}  // namespace hexadapt
