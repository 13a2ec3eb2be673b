// Size metrics of quads and hexes: edge lengths and a stable time-step length, pure
// functions of the corner points (corner order as in geometry.h).
//
// An explicit Lagrangian solver's time step follows the smallest length across a cell, and
// the scaled Jacobian says nothing about it: a quad with one edge a thousandth of the others
// can still score 0.77. These metrics give the size side of a mesh's worth:
// - edge lengths (shortest, longest, mean) and Verdict's edge ratio, longest / shortest
//   (Stimpson et al., SAND2007-1751; 1 for a square or a cube);
// - the time-step length, the cell's measure divided by its largest boundary measure: hex
//   volume / largest face area (a non-planar face's area is half the norm of its diagonals'
//   cross product), quad area / longest edge. For a square or a cube of side h it is h.
// A degenerate cell (an edge shorter than 1e-13 of the longest, a NaN) has a shortest edge
// of 0 and an edge ratio of +infinity, never a finite "good" value.
#pragma once

#include <array>
#include <limits>

#include "hexadapt/core/geometry.h"

namespace hexadapt {

struct EdgeLengths {
  double min = 0, max = 0, mean = 0;
  /// Verdict's edge ratio, max / min (+infinity when min is 0).
  double ratio() const;
};

EdgeLengths hex_edge_lengths(const std::array<Vec3, 8>& p);
EdgeLengths quad_edge_lengths(const std::array<Vec3, 4>& p);

/// A hex's scaled Jacobian (scaled_jacobian.h) and shortest edge (hex_edge_lengths(p).min)
/// from one pass over its edges: the two apart cost twice as much.
struct HexShapeAndSize {
  double scaled_jacobian = -1;
  double shortest_edge = 0;
};
/// Where only two questions matter, whether the shortest edge reaches `min_edge` and whether
/// the scaled Jacobian reaches `stop_below`: the Jacobian is not computed (left at -1) when
/// the shortest edge is below min_edge, and is exact when at least stop_below, else some
/// value below it (the corners are not all computed).
HexShapeAndSize hex_shape_and_size(
    const std::array<Vec3, 8>& p, double min_edge = 0,
    double stop_below = -std::numeric_limits<double>::infinity());

/// What a cell can still reach while only its corner `moving` (binary order for a hex,
/// counter-clockwise for a quad) moves: its scaled Jacobian stays at or below
/// `scaled_jacobian` (the corners whose frames do not hold the moving corner), its shortest
/// edge at or below `shortest_edge` (the edges not touching it).
struct ShapeAndSizeBound {
  double scaled_jacobian = 1;
  double shortest_edge = 0;
};
ShapeAndSizeBound hex_bound_moving(const std::array<Vec3, 8>& p, std::size_t moving);
ShapeAndSizeBound quad_bound_moving(const std::array<Vec3, 4>& p, std::size_t moving);

/// Hex volume / largest face area (0 for an inverted or degenerate hex).
double hex_time_step_length(const std::array<Vec3, 8>& p);
/// Quad area (xy plane) / longest edge (0 for an inverted or degenerate quad).
double quad_time_step_length(const std::array<Vec3, 4>& p);

}  // namespace hexadapt
