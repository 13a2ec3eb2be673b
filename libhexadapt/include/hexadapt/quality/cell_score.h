// The one number per cell that the guarantee's two criteria come down to (DESIGN sec. 6): the
// shape, scaled Jacobian >= S_q (paper sec. 5), and the size, shortest edge >= a minimum
// length (a share, default_min_edge, of the cell's local input size), so that no sliver cuts
// an explicit solver's time step. The scaled Jacobian says nothing about size: a quad with one
// edge a thousandth of the others can score 0.77.
//
// The score is the scaled Jacobian when the size criterion holds, and -2 + shortest / minimum
// length, in [-2, -1), when it does not. A cell that breaks the size criterion therefore
// scores below every scaled Jacobian, so "every cell >= S_q" means both criteria, and "never
// lower the local minimum" (smoothing) never makes a sliver where there was none and
// lengthens the short edge of one that is there. With a minimum length of 0 (size criterion
// off) the score is the scaled Jacobian. Every move, mend and check of adapt compares these
// scores (adapt/size_criterion.h gives each cell its minimum length).
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "hexadapt/core/geometry.h"

namespace hexadapt {

/// The score from a scaled Jacobian and a shortest edge (or bounds of them).
inline double score_of(double scaled_jacobian, double shortest_edge, double min_length) {
  if (!(min_length > 0)) return scaled_jacobian;
  const double r = shortest_edge / min_length;
  return r < 1 ? -2.0 + r : scaled_jacobian;
}

/// A hex's score; exact when at least `stop_below`, else some value below it (the Jacobian
/// is then computed only as far as needed, not at all when the size criterion fails).
double hex_score(const std::array<Vec3, 8>& p, double min_length,
                 double stop_below = -std::numeric_limits<double>::infinity());
/// A quad's score.
double quad_score(const std::array<Vec3, 4>& p, double min_length);

/// The highest score the cell can reach while only its corner `moving` moves (binary order
/// for a hex, counter-clockwise for a quad): -2 + the shortest edge not touching it / min
/// length when that one already breaks the size criterion, else the scaled Jacobian of the
/// corners whose frames do not hold it (cell_size.h). When the cell scores it already, no
/// move of that corner raises its score.
double hex_score_bound(const std::array<Vec3, 8>& p, std::size_t moving, double min_length);
double quad_score_bound(const std::array<Vec3, 4>& p, std::size_t moving, double min_length);

}  // namespace hexadapt
