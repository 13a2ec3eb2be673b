// The cell of a grid that holds a point: the local size of a measured cell is read from the
// reference cell holding its centroid (size_report.h).
//
// A cell holds a point when the point lies in the region the imprint gives the cell (its
// convex pieces, cell_pieces.h), within 1e-9 of the cell's diagonal; among several, the
// lowest id. A point no cell holds (outside the grid, or in a gap left by folded faces)
// goes to the cell whose centroid is nearest (the lowest id among equal distances).
// Candidates come from bins over the cells' boxes (cell_bins.h): the cost is linear in the
// points when the grid's cells have about equal sizes.
#pragma once

#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/core/log.h"

namespace hexadapt {
namespace io {
struct MeshData;
}

struct PointCells {
  std::vector<index_t> cell;  ///< per point: the grid cell holding it, or the nearest one
                              ///< (-1 for a point with a NaN coordinate)
  index_t outside = 0;        ///< points no cell holds
};

/// The grid must have cells and valid node ids. `progress` (phase "size") goes from `from`
/// to `to` over the points.
PointCells locate(const io::MeshData& grid, const std::vector<Vec3>& points,
                  const Progress& progress, double from, double to);

}  // namespace hexadapt
