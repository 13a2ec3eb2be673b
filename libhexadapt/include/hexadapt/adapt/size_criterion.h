// The size criterion of the guarantee (DESIGN sec. 6), beside the shape one (scaled Jacobian
// >= S_q, paper sec. 5): every cell keeps its shortest edge at least `min_edge` times its
// local input size, so that no sliver cuts an explicit solver's time step. The scaled
// Jacobian says nothing about size: a quad with one edge a thousandth of the others can
// score 0.77.
//
// Local input size: the mean edge length of the input-grid cell a cell comes from (a pillow
// layer cell: the cell it was inflated from). Moves never change it; pillowing carries it
// through its cell-origin maps (remapped). The output mesh holds it as the `local_size` cell
// array, which hexadapt-measure checks the criterion against.
//
// The adaptation steps compare one number per cell, the score: the scaled Jacobian when the
// size criterion holds, and -2 + shortest / (min_edge x local size), in [-2, -1), when it does
// not. A cell that breaks the size criterion therefore scores below every scaled Jacobian,
// so "every cell around the node >= S_q" (controlled move, cavities) means both criteria, and
// "never lower the local minimum" (smoothing) never makes a sliver where there was none and
// lengthens the short edge of one that is there. Where the criterion holds nothing changes:
// with min_edge 0 (off) the score is the scaled Jacobian.
#pragma once

#include <limits>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/quality/cell_size.h"

namespace hexadapt {

struct SizeCriterion {
  double min_edge = 0;                  ///< shortest edge / local size at least; 0 = off
  IdVector<CellId, double> local_size;  ///< per cell of the mesh it is used on

  bool on() const { return min_edge > 0; }
  /// The shortest edge cell c may have.
  double min_length(CellId c) const { return on() ? min_edge * local_size[c] : 0.0; }
  /// The criterion for a mesh whose cell k comes from cell origin[k] of this one's mesh.
  SizeCriterion remapped(const std::vector<CellId>& origin) const;
};

/// Shortest, longest and mean edge of a cell.
template <class M>
EdgeLengths cell_edge_lengths(const M& mesh, CellId c) {
  if constexpr (M::dim == 3) {
    return hex_edge_lengths(mesh.cell_points(c));
  } else {
    return quad_edge_lengths(mesh.cell_points(c));
  }
}

/// The local size of every cell of an input grid: its mean edge length.
template <class M>
IdVector<CellId, double> mean_edge_lengths(const M& grid);

/// The smallest shortest edge / local size over the mesh's cells (`size.local_size`); 0 for a
/// mesh without cells.
template <class M>
double min_edge_ratio(const M& mesh, const SizeCriterion& size);

/// The criterion `min_edge` on the cells of `grid` itself (local sizes kept even when off).
template <class M>
SizeCriterion size_criterion(const M& grid, double min_edge) {
  return {min_edge, mean_edge_lengths(grid)};
}

/// Mean local size of the cells around n (0 when it has none); `size` must carry the sizes.
template <class M>
double node_local_size(const M& mesh, NodeId n, const SizeCriterion& size) {
  double h = 0;
  int count = 0;
  for (CellId c : mesh.node_cells(n)) {
    h += size.local_size[c];
    ++count;
  }
  return count ? h / count : 0.0;
}

/// Shortest edge / (min_edge x local size): below 1 breaks the criterion (+inf when off).
template <class M>
double size_ratio(const M& mesh, CellId c, const SizeCriterion& size);

/// The score of cell c from its scaled Jacobian and its shortest edge (or bounds of them).
inline double score_of(double scaled_jacobian, double shortest_edge, CellId c,
                       const SizeCriterion& size) {
  if (!size.on()) return scaled_jacobian;
  const double r = shortest_edge / size.min_length(c);
  return r < 1 ? -2.0 + r : scaled_jacobian;
}

/// The scaled Jacobian, or -2 + size_ratio in [-2, -1) when the size criterion fails. Exact
/// when at least `stop_below`; below it, a hex's score may be any value below it (its
/// Jacobian is then computed only as far as needed).
template <class M>
double cell_score(const M& mesh, CellId c, const SizeCriterion& size,
                  double stop_below = -std::numeric_limits<double>::infinity()) {
  if constexpr (M::dim == 3) {  // the hex's edges once for both criteria
    const HexShapeAndSize m =
        hex_shape_and_size(mesh.cell_points(c), size.min_length(c), stop_below);
    return score_of(m.scaled_jacobian, m.shortest_edge, c, size);
  } else {
    if (!size.on()) return mesh.cell_quality(c);
    const double r = size_ratio(mesh, c, size);
    return r < 1 ? -2.0 + r : mesh.cell_quality(c);
  }
}

/// The highest score cell c can reach while only its node `moving` (its index in the cell's
/// nodes) moves: -2 + the shortest edge not touching it / min length when that one already
/// breaks the size criterion, else the scaled Jacobian of the corners whose frames do not
/// hold it (cell_size.h). When c scores it already, no move of that node raises c's score.
template <class M>
double cell_score_bound(const M& mesh, CellId c, const SizeCriterion& size, std::size_t moving) {
  ShapeAndSizeBound b;
  if constexpr (M::dim == 3)
    b = hex_bound_moving(mesh.cell_points(c), moving);
  else
    b = quad_bound_moving(mesh.cell_points(c), moving);
  return score_of(b.scaled_jacobian, b.shortest_edge, c, size);
}

/// Smallest score of the cells around n (1 when n has no cell). With `stop_below`, returns
/// as soon as a cell scores below it: the result is then below it, but not always the
/// smallest (a trial position that must reach a bound is refused at its first bad cell).
template <class M>
double min_score_around(const M& mesh, NodeId n, const SizeCriterion& size,
                        double stop_below = -std::numeric_limits<double>::infinity()) {
  double s = 1.0;
  for (CellId c : mesh.node_cells(n)) {
    s = std::min(s, cell_score(mesh, c, size, stop_below));
    if (s < stop_below) break;
  }
  return s;
}

/// A cell that breaks a criterion, and by how much.
struct CellFailure {
  CellId cell;
  double scaled_jacobian = 0;
  double shortest_edge = 0;
  double min_length = 0;  ///< the shortest edge it may have (0: size criterion off)
  Vec3 centroid = Vec3::Zero();
  bool shape_failed(double threshold) const { return scaled_jacobian < threshold; }
  bool size_failed() const { return shortest_edge < min_length; }
  /// cell_score's value: -2 + shortest / min_length when the size fails, else the Jacobian.
  double score() const {
    return size_failed() ? -2.0 + shortest_edge / min_length : scaled_jacobian;
  }
};

/// Every cell with scaled Jacobian < threshold or shortest edge < its min_length, by id.
template <class M>
std::vector<CellFailure> failing_cells(const M& mesh, double threshold, const SizeCriterion& size);

/// The `count` worst of `failures` (lowest score first, then by id).
std::vector<CellFailure> worst_failures(std::vector<CellFailure> failures, std::size_t count);

}  // namespace hexadapt
