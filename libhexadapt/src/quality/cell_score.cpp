#include "hexadapt/quality/cell_score.h"

#include "hexadapt/quality/cell_size.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

double hex_score(const std::array<Vec3, 8>& p, double min_length, double stop_below) {
  // The hex's edges once for both criteria.
  const HexShapeAndSize m = hex_shape_and_size(p, min_length, stop_below);
  return score_of(m.scaled_jacobian, m.shortest_edge, min_length);
}

double quad_score(const std::array<Vec3, 4>& p, double min_length) {
  const double shortest = min_length > 0 ? quad_edge_lengths(p).min : 0.0;
  return score_of(quad_scaled_jacobian(p), shortest, min_length);
}

double hex_score_bound(const std::array<Vec3, 8>& p, std::size_t moving, double min_length) {
  const ShapeAndSizeBound b = hex_bound_moving(p, moving);
  return score_of(b.scaled_jacobian, b.shortest_edge, min_length);
}

double quad_score_bound(const std::array<Vec3, 4>& p, std::size_t moving, double min_length) {
  const ShapeAndSizeBound b = quad_bound_moving(p, moving);
  return score_of(b.scaled_jacobian, b.shortest_edge, min_length);
}

}  // namespace hexadapt
