#include "hexadapt/io/material_array.h"

#include <cmath>
#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt::io {

IdVector<CellId, int> read_material_array(const MeshData& data, int n_materials,
                                          const std::string& file, const std::string& array) {
  const DataArray* a = data.find_cell_array(array);
  if (a == nullptr)
    throw InputError(file, "cell data",
                     "no '" + array + "' cell array: the grid is not assigned (the assign stage "
                         "writes it)");
  if (a->n_components != 1 || a->n_tuples() != static_cast<std::size_t>(data.n_cells()))
    throw InputError(file, "cell array '" + array + "'",
                     "expected one value per cell (" + std::to_string(data.n_cells()) + ")");
  IdVector<CellId, int> out(static_cast<std::size_t>(data.n_cells()));
  for (CellId c : id_range<CellId>(data.n_cells())) {
    const double v = a->values[c.idx()];
    if (!(v >= 0 && v < n_materials && v == std::floor(v)))
      throw InputError(file, "cell " + std::to_string(c.value()),
                       "'" + array + "' is " + std::to_string(v) +
                           ", expected a material index in [0, " + std::to_string(n_materials) +
                           ")");
    out[c] = static_cast<int>(v);
  }
  return out;
}

}  // namespace hexadapt::io
