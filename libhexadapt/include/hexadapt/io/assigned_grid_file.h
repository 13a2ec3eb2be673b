// An assigned grid (mesh/assigned_grid.h) in a file's data: the one reader and writer the
// stages share. In a file the grid keeps
//   - each material's fractions in a cell array vf_<name> (or what FractionOptions names),
//   - each cell's material index in the cell array `material`,
//   - the material names in the metadata entry `hexadapt_materials` (material_names.h).
#pragma once

#include <string>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/material_names.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/assigned_grid.h"

namespace hexadapt::io {

/// Where each cell's material comes from.
enum class MaterialSource {
  array,     ///< the `material` cell array (the assign stage writes it)
  majority,  ///< each cell's majority material: a grid read as if assigned by eq. (2)
  none,      ///< not read: the grid's material stays empty (a grid to assign, a reference)
};

struct AssignedGridOptions {
  FractionOptions fractions;
  MaterialSource material = MaterialSource::array;
  std::string material_array = "material";  ///< the cell array MaterialSource::array reads
};

/// The assigned grid `data` holds (read from `file`, which errors name): its mesh, its
/// fractions (extract_fractions, which fills `report`) and each cell's material from
/// options.material. Throws InputError as extract_fractions, to_mesh and read_material_array.
/// `block`: the data is one rank's block of a distributed grid (extract_fractions).
AssignedGrid to_assigned_grid(const MeshData& data, const AssignedGridOptions& options,
                              const std::string& file, FractionReport* report = nullptr,
                              const dist::Block* block = nullptr);

/// Writes the fractions (vf_<name>), the material (when assigned) and the names of `grid`
/// into `data`, which holds its mesh: the arrays replace those of the same names.
void put_assignment(const AssignedGrid& grid, MeshData& data);

/// The file data of `grid`: its mesh (from_mesh) with put_assignment's arrays.
MeshData to_mesh_data(const AssignedGrid& grid);

/// The `array` cell array of `data`: whole numbers in [0, n_materials). Throws InputError
/// naming `file` and what is wrong: no such array, not one value per cell, or the first cell
/// whose value is not a material index (named by its id in the whole grid when `block`, one
/// rank's part of it, is given).
CellMaterials read_material_array(const MeshData& data, int n_materials, const std::string& file,
                                  const std::string& array = "material",
                                  const dist::Block* block = nullptr);

}  // namespace hexadapt::io
