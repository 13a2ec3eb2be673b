// Cutting a cell by a plane: the volume on one side, and the plane of a given normal that
// leaves a given share of the cell on that side (the PLIC step of volume-of-fluid
// reconstruction), with which interface targets (paper sec. 5, DESIGN 4.3) can place a
// planar interface exactly from the volume fractions.
//
// A quad is clipped as a polygon; a hex is split into the six tetrahedra around its
// diagonal 0-7 (the same split for every hex) and each one is clipped by the half-space.
#pragma once

#include <optional>

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt {

/// Area (2D) or volume (3D) of the part of cell c where n . x >= s.
template <class M>
double volume_above_plane(const M& mesh, CellId c, const Vec3& n, double s);

/// The offset s such that the part of cell c where n . x >= s holds `share` (in (0, 1)) of
/// the cell, found by bisection on the monotone volume function; nullopt when the cell is
/// degenerate (no volume) or share is not strictly inside (0, 1).
template <class M>
std::optional<double> plane_offset_for_share(const M& mesh, CellId c, const Vec3& n, double share);

}  // namespace hexadapt
