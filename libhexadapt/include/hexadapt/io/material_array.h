// The per-cell material of an assigned grid (the `material` cell array hexadapt-assign
// writes): the one reader the stages after assign share.
#pragma once

#include <string>

#include "hexadapt/core/ids.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io {

/// The `array` cell array of `data`: whole numbers in [0, n_materials). Throws InputError
/// naming `file` and what is wrong: no such array, not one value per cell, or the first cell
/// whose value is not a material index.
IdVector<CellId, int> read_material_array(const MeshData& data, int n_materials,
                                          const std::string& file,
                                          const std::string& array = "material");

}  // namespace hexadapt::io
