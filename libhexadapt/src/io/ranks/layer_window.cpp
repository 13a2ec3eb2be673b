// ReadOptions::layers on a structured grid read whole: its points, cells and arrays cut to
// a window of layers across its last axis. Ids are structured (cell (i, j, k) is
// i + nx (j + ny k)), so a window of layers is one contiguous range of cells and of points.
#include <algorithm>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::io {

namespace {

void keep_range(DataArray& a, std::size_t first, std::size_t end) {
  const auto n = static_cast<std::size_t>(a.n_components);
  a.values.erase(a.values.begin() + static_cast<std::ptrdiff_t>(end * n), a.values.end());
  a.values.erase(a.values.begin(), a.values.begin() + static_cast<std::ptrdiff_t>(first * n));
}

}  // namespace

void keep_layers(MeshData& data, const std::array<int, 2>& layers, const std::string& file) {
  std::array<int, 3>& cells = data.structured_cells;
  if (data.dim == 0 || cells[0] == 0)
    throw OptionError(file +
                      ": a window of layers needs a structured grid (.vti .vtr .vts, their "
                      "parallel forms .pvti .pvtr .pvts, or a structured .vtk)");
  const auto axis = static_cast<std::size_t>(data.dim - 1);
  const auto [first, end] = layers;
  if (first < 0 || end <= first || end > cells[axis])
    throw InputError(file, "",
                     "cell layers " + std::to_string(first) + " to " + std::to_string(end) +
                         " are not inside the grid's " + std::to_string(cells[axis]) + " layers");
  std::size_t cells_per_layer = 1, points_per_layer = 1;
  for (std::size_t a = 0; a < axis; ++a) {
    cells_per_layer *= static_cast<std::size_t>(cells[a]);
    points_per_layer *= static_cast<std::size_t>(cells[a]) + 1;
  }
  const auto f = static_cast<std::size_t>(first), e = static_cast<std::size_t>(end);
  for (DataArray& a : data.cell_data) keep_range(a, f * cells_per_layer, e * cells_per_layer);
  for (DataArray& a : data.point_data)
    keep_range(a, f * points_per_layer, (e + 1) * points_per_layer);
  data.points.erase(data.points.begin() + static_cast<std::ptrdiff_t>((e + 1) * points_per_layer),
                    data.points.end());
  data.points.erase(data.points.begin(),
                    data.points.begin() + static_cast<std::ptrdiff_t>(f * points_per_layer));
  cells[axis] = end - first;
  data.cells.clear();
  append_structured_cells(cells[0], cells[1], data.dim == 3 ? cells[2] : 0, data.cells);
}

}  // namespace hexadapt::io
