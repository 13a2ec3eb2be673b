// Shape metrics of quads and hexes (Verdict, Stimpson et al., SAND2007-1751; Knupp,
// "Algebraic mesh quality metrics", 2001): pure functions of the corner points.
//
// Shape is 1 for a square / cube, decreases with any deviation from it (stretching as well
// as skew, unlike the scaled Jacobian which ignores stretching), and is 0 for inverted or
// degenerate cells. Hex: the minimum over the 8 corners of 3 det(A)^(2/3) / |A|_F^2, where A
// holds the three edges leaving the corner (as ParaView's HexShape). Quad (xy plane,
// counter-clockwise): the minimum over the 4 corners of 2 cross(a, b).z / (|a|^2 + |b|^2)
// (as ParaView's QuadShape on counter-clockwise quads). Corner order as in geometry.h.
#pragma once

#include <array>

#include "hexadapt/core/geometry.h"

namespace hexadapt {

/// Verdict hex shape, in [0, 1].
double hex_shape(const std::array<Vec3, 8>& p);
/// Verdict quad shape with the +z orientation, in [0, 1].
double quad_shape(const std::array<Vec3, 4>& p);

}  // namespace hexadapt
