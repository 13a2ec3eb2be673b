// The files of the adaptation stage (DESIGN sec. 2): reading an assigned grid (`material`
// cell array + volume-fraction arrays) and turning an adaptation result into the output mesh
// with its `material` cell array and the `target` and `distance` point arrays (targets can
// be shown as arrows in ParaView: target - position).
#pragma once

#include <string>
#include <vector>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

/// The per-cell material of an assigned grid: the `array` cell array, whole numbers in
/// [0, n_materials). Throws InputError naming `file` and the first bad cell.
IdVector<CellId, int> read_material_array(const io::MeshData& data, int n_materials,
                                          const std::string& file,
                                          const std::string& array = "material");

/// The output mesh: points, cells, `material` (int32) and `local_size` (each cell's local
/// input size, size_criterion.h) cell arrays, `target` (3 components), `distance` and
/// `surface_distance` point arrays; the material names in the `materials` metadata entry.
template <class M>
io::MeshData adapt_mesh_data(const AdaptResult<M>& result,
                             const std::vector<std::string>& material_names);

}  // namespace hexadapt
