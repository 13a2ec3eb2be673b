// Points or cells as rows of doubles (coordinates, then every array's components), the form
// in which they travel between ranks (vtk_collection_merge.cpp, mesh_part.cpp).
#pragma once

#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io::detail {

/// The row width: 3 with points, plus every array's components.
int row_width(bool with_points, const std::vector<DataArray>& arrays);

/// Tuple i's row for i in [0, n): its point when `points` is given, then every array's tuple.
std::vector<double> rows_of(const std::vector<Vec3>* points, const std::vector<DataArray>& arrays,
                            std::size_t n);

/// The inverse: n rows into `points` (when given) and the arrays, resized to n tuples.
void set_rows(const std::vector<double>& rows, std::size_t n, std::vector<Vec3>* points,
              std::vector<DataArray>& arrays);

}  // namespace hexadapt::io::detail
