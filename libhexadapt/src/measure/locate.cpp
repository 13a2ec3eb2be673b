// The grid cell holding each point, or the nearest by centroid (see locate.h).
#include "locate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cell_bins.h"
#include "cell_pieces.h"
#include "cell_values.h"
#include "hexadapt/core/parallel_progress.h"

namespace hexadapt {

namespace {

constexpr double hold_tolerance = 1e-9;     // relative to the cell's diagonal
constexpr double convex_tolerance = 1e-12;  // as the imprint's default (ImprintOptions)

// Inside the cell's pieces: the hull less its notches, or the union of its tetrahedra.
bool holds(const io::MeshData& grid, const CellBins& bins, index_t c, const Vec3& p) {
  const double eps = hold_tolerance * bins.box(c).diagonal().norm();
  double volume = 0, inside = 0;
  for (const clip::Piece& piece : clip::convex_pieces(grid, c, convex_tolerance, &volume))
    if (std::all_of(piece.planes.begin(), piece.planes.end(),
                    [&](const clip::Plane& pl) { return pl.side(p) <= eps; }))
      inside += piece.sign;
  return inside > 0;
}

// The nearest centroid among `cells` (increasing ids: the lowest id wins a tie).
index_t nearest_of(const std::vector<index_t>& cells, const std::vector<Vec3>& centroids,
                   const Vec3& p, double* distance) {
  index_t best = -1;
  *distance = std::numeric_limits<double>::infinity();
  for (index_t c : cells) {
    const double d = (centroids[static_cast<std::size_t>(c)] - p).norm();
    if (d < *distance) {
      *distance = d;
      best = c;
    }
  }
  return best;
}

// Grows a box around p until it holds a centroid at a distance no larger than its half
// side: every nearer centroid's cell then overlaps the box too. Once the box covers the
// grid, every cell is a candidate (flat boxes overlap nothing). -1 only for NaN points.
index_t nearest_centroid(const CellBins& bins, const std::vector<Vec3>& centroids, const Vec3& p,
                         std::vector<index_t>& scratch) {
  const Eigen::AlignedBox3d& domain = bins.domain();
  double r = domain.exteriorDistance(p) + 1e-3 * domain.diagonal().norm();
  for (;;) {
    const Eigen::AlignedBox3d q(p - Vec3::Constant(r), p + Vec3::Constant(r));
    const bool everything = !std::isfinite(r) || q.contains(domain);
    if (everything) {
      scratch.resize(centroids.size());
      for (std::size_t c = 0; c < scratch.size(); ++c) scratch[c] = static_cast<index_t>(c);
    } else {
      bins.query(q, scratch);
    }
    double d = 0;
    const index_t best = nearest_of(scratch, centroids, p, &d);
    if (everything || (best >= 0 && d <= r)) return best;
    r = best >= 0 ? d : 2 * r;
  }
}

}  // namespace

PointCells locate(const io::MeshData& grid, const std::vector<Vec3>& points,
                  const Progress& progress, double from, double to) {
  const CellBins bins(grid, 1.0);
  std::vector<Vec3> centroids(static_cast<std::size_t>(grid.n_cells()));
  for (std::size_t c = 0; c < centroids.size(); ++c) centroids[c] = centroid(grid, c);
  PointCells r;
  r.cell.assign(points.size(), -1);
  std::vector<char> outside(points.size(), 0);
  auto one_point = [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    thread_local std::vector<index_t> candidates;
    bins.query_point(points[k], candidates);
    for (index_t c : candidates)
      if (holds(grid, bins, c, points[k])) {
        r.cell[k] = c;
        return;
      }
    r.cell[k] = nearest_centroid(bins, centroids, points[k], candidates);
    outside[k] = 1;
  };
  parallel_for_progress(static_cast<std::int64_t>(points.size()), progress, "size", one_point, from,
                        to);
  r.outside = static_cast<index_t>(std::count(outside.begin(), outside.end(), 1));
  return r;
}

}  // namespace hexadapt
