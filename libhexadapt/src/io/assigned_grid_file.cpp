#include "hexadapt/io/assigned_grid_file.h"

#include <cmath>
#include <string>
#include <utility>

#include "hexadapt/core/error.h"

namespace hexadapt::io {

namespace {

CellMaterials materials_of(const MeshData& data, const Fractions& fractions,
                           const AssignedGridOptions& options, const std::string& file,
                           const dist::Block* block) {
  switch (options.material) {
    case MaterialSource::array:
      return read_material_array(data, fractions.n_materials(), file, options.material_array,
                                 block);
    case MaterialSource::majority:
      return majority_materials(fractions);
    case MaterialSource::none:
      break;
  }
  return {};
}

}  // namespace

AssignedGrid to_assigned_grid(const MeshData& data, const AssignedGridOptions& options,
                              const std::string& file, FractionReport* report,
                              const dist::Block* block) {
  AssignedGrid grid;
  grid.fractions = extract_fractions(data, options.fractions, report, file, block);
  grid.material = materials_of(data, grid.fractions, options, file, block);
  grid.mesh = to_mesh(data, file);
  return grid;
}

void put_assignment(const AssignedGrid& grid, MeshData& data) {
  const Fractions& f = grid.fractions;
  for (int m = 0; m < f.n_materials(); ++m) {
    DataArray a;
    a.name = "vf_" + f.names()[static_cast<std::size_t>(m)];
    for (CellId c : id_range<CellId>(f.n_cells())) a.values.push_back(f(c, m));
    data.set_cell_array(std::move(a));
  }
  if (grid.assigned()) {
    DataArray a;
    a.name = "material";
    a.type = ScalarType::int32;
    a.values.assign(grid.material.begin(), grid.material.end());
    data.set_cell_array(std::move(a));
  }
  set_material_names(data, f.names());
}

MeshData to_mesh_data(const AssignedGrid& grid) {
  MeshData data = from_mesh(grid.mesh);
  put_assignment(grid, data);
  return data;
}

CellMaterials read_material_array(const MeshData& data, int n_materials, const std::string& file,
                                  const std::string& array, const dist::Block* block) {
  const DataArray* a = data.find_cell_array(array);
  if (a == nullptr)
    throw InputError(file, "cell data",
                     "no '" + array +
                         "' cell array: the cells' materials are missing (the "
                         "assign and adapt stages write them)");
  if (a->n_components != 1 || a->n_tuples() != static_cast<std::size_t>(data.n_cells()))
    throw InputError(file, "cell array '" + array + "'",
                     "expected one value per cell (" + std::to_string(data.n_cells()) + ")");
  CellMaterials out(static_cast<std::size_t>(data.n_cells()));
  for (CellId c : id_range<CellId>(data.n_cells())) {
    const double v = a->values[c.idx()];
    if (!(v >= 0 && v < n_materials && v == std::floor(v)))
      throw InputError(file, "cell " + std::to_string(dist::global_cell(block, c)),
                       "'" + array + "' is " + std::to_string(v) +
                           ", expected a material index in [0, " + std::to_string(n_materials) +
                           ")");
    out[c] = static_cast<int>(v);
  }
  return out;
}

}  // namespace hexadapt::io
