// The size criterion of the guarantee (DESIGN sec. 6) on a mesh: every cell keeps its shortest
// edge at least `min_edge` times its local input size; the score that holds it together with
// the shape criterion is quality/cell_score.h's, here taken cell by cell.
//
// Local input size: the mean edge length of the input-grid cell a cell comes from (a pillow
// layer cell: the cell it was inflated from). Moves never change it; pillowing carries it
// through its cell-origin maps (remapped). The output mesh holds it as the `local_size` cell
// array, which hexadapt-measure checks the criterion against.
#pragma once

#include <limits>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/quality/cell_score.h"
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

/// Cell c's score (quality/cell_score.h) with its minimum length. Exact when at least
/// `stop_below`; below it, a hex's score may be any value below it.
template <class M>
double cell_score(const M& mesh, CellId c, const SizeCriterion& size,
                  double stop_below = -std::numeric_limits<double>::infinity()) {
  if constexpr (M::dim == 3)
    return hex_score(mesh.cell_points(c), size.min_length(c), stop_below);
  else
    return quad_score(mesh.cell_points(c), size.min_length(c));
}

/// The highest score cell c can reach while only its node `moving` (its index in the cell's
/// nodes) moves (hex_score_bound).
template <class M>
double cell_score_bound(const M& mesh, CellId c, const SizeCriterion& size, std::size_t moving) {
  if constexpr (M::dim == 3)
    return hex_score_bound(mesh.cell_points(c), moving, size.min_length(c));
  else
    return quad_score_bound(mesh.cell_points(c), moving, size.min_length(c));
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
  /// Its score (quality/cell_score.h).
  double score() const { return score_of(scaled_jacobian, shortest_edge, min_length); }
};

/// Every cell with scaled Jacobian < threshold or shortest edge < its min_length, by id.
template <class M>
std::vector<CellFailure> failing_cells(const M& mesh, double threshold, const SizeCriterion& size);

/// The `count` worst of `failures` (lowest score first, then by id).
std::vector<CellFailure> worst_failures(std::vector<CellFailure> failures, std::size_t count);

}  // namespace hexadapt
