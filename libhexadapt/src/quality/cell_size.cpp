#include "hexadapt/quality/cell_size.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frames.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

namespace {

// Below this share of the longest edge an edge counts as collapsed (as in scaled_jacobian).
constexpr double degenerate_share = 1e-13;

// The shortest edge as reported: 0 when it is collapsed next to the longest.
double reported_shortest(double shortest, double longest) {
  return shortest > degenerate_share * longest ? shortest : 0.0;
}

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
