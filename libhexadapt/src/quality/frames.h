// The corner frames and principal axes that the Verdict metrics (scaled Jacobian, shape)
// are built from, shared by scaled_jacobian.cpp and shape.cpp.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "hexadapt/core/geometry.h"

namespace hexadapt::quality_detail {

/// A frame vector shorter than this times the cell's longest edge is a collapsed edge: the
/// cell is degenerate (relative, so that the test does not depend on the units).
inline constexpr double degenerate_length = 1e-13;

/// The three edges leaving hex corner v, ordered so that they form a right-handed frame in
/// a positively oriented hex (Verdict's corner Jacobian): towards the neighbours along x, y,
/// z, with x and y swapped at the corners of odd parity (an odd number of "upper" bits
/// mirrors the frame).
inline std::array<Vec3, 3> hex_corner_frame(const std::array<Vec3, 8>& p, std::size_t v) {
  const Vec3 a = p[v ^ 1u] - p[v], b = p[v ^ 2u] - p[v], c = p[v ^ 4u] - p[v];
  const unsigned parity = (v & 1u) ^ ((v >> 1) & 1u) ^ ((v >> 2) & 1u);
  if (parity) return {b, a, c};
  return {a, b, c};
}

/// Differences of the centroids of opposite faces (times 4): the Jacobian at the centre.
inline std::array<Vec3, 3> hex_principal_axes(const std::array<Vec3, 8>& p) {
  return {(p[1] + p[3] + p[5] + p[7]) - (p[0] + p[2] + p[4] + p[6]),
          (p[2] + p[3] + p[6] + p[7]) - (p[0] + p[1] + p[4] + p[5]),
          (p[4] + p[5] + p[6] + p[7]) - (p[0] + p[1] + p[2] + p[3])};
}

/// The 12 edges of a hex (ref_hex::edges order, from the lower to the upper corner), their
/// lengths and the longest, computed once for the metrics that all need them.
struct HexEdges {
  std::array<Vec3, 12> vec;
  std::array<double, 12> length;
  double longest = 0;
};

/// Edge K of hex_edges, K known at compile time (the ends' indices fold away).
template <std::size_t K>
[[gnu::always_inline]] inline void hex_edge(const std::array<Vec3, 8>& p, HexEdges& e) {
  constexpr auto ends = ref_hex::edges[K];
  e.vec[K] = p[static_cast<std::size_t>(ends[1])] - p[static_cast<std::size_t>(ends[0])];
  e.length[K] = e.vec[K].norm();
  e.longest = std::max(e.longest, e.length[K]);
}

template <std::size_t... K>
[[gnu::always_inline]] inline HexEdges hex_edges(const std::array<Vec3, 8>& p,
                                                 std::index_sequence<K...>) {
  HexEdges e;
  (hex_edge<K>(p, e), ...);
  return e;
}

inline HexEdges hex_edges(const std::array<Vec3, 8>& p) {
  return hex_edges(p, std::make_index_sequence<12>{});
}

/// The index in ref_hex::edges of the edge leaving corner v along axis 0, 1 or 2.
constexpr std::size_t hex_edge_index(std::size_t v, int axis) {
  if (axis == 0) return (v & 6u) >> 1;
  if (axis == 1) return 4 + ((v & 1u) | ((v >> 1) & 2u));
  return 8 + (v & 3u);
}

/// hex_scaled_jacobian(p) from p's edges (scaled_jacobian.cpp), exact when it is at least
/// `stop_below`; otherwise some value below stop_below (it stops at the first corner below).
double hex_scaled_jacobian(const std::array<Vec3, 8>& p, const HexEdges& e, double stop_below);

/// The largest scaled Jacobian the hex can have while only its corner `moving` moves: the
/// smallest Jacobian of the four corners whose frames do not hold it, computed as
/// hex_scaled_jacobian computes them (1 when one of their edges has no direction). The other
/// corners and the centre only lower the score.
double hex_scaled_jacobian_bound(const HexEdges& e, std::size_t moving);
/// The same for a quad: the Jacobian of the corner opposite `moving`.
double quad_scaled_jacobian_bound(const std::array<Vec3, 4>& p, std::size_t moving);

/// The longest of the 12 edges: the length unit of the degeneracy test.
inline double hex_scale(const std::array<Vec3, 8>& p) {
  double s = 0;
  for (const auto& e : ref_hex::edges)
    s = std::max(s, (p[static_cast<std::size_t>(e[1])] - p[static_cast<std::size_t>(e[0])]).norm());
  return s;
}

/// The two edges leaving quad corner v in the xy plane: towards the next and the previous
/// corner, so that cross(next, prev).z > 0 for a counter-clockwise quad.
inline std::pair<Eigen::Vector2d, Eigen::Vector2d> quad_corner_frame(const std::array<Vec3, 4>& p,
                                                                     std::size_t v) {
  return {(p[(v + 1) % 4] - p[v]).head<2>(), (p[(v + 3) % 4] - p[v]).head<2>()};
}

inline double quad_scale(const std::array<Vec3, 4>& p) {
  double s = 0;
  for (std::size_t v = 0; v < 4; ++v) s = std::max(s, (p[(v + 1) % 4] - p[v]).head<2>().norm());
  return s;
}

}  // namespace hexadapt::quality_detail
