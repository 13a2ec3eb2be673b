// The files of the adaptation stage (DESIGN sec. 2): an assigned grid is read with
// io/fractions_reader.h and io/material_array.h; here an adaptation result becomes the output mesh
// with its `material` cell array and the `target` and `distance` point arrays (targets can
// be shown as arrows in ParaView: target - position).
#pragma once

#include <string>
#include <vector>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

/// The output mesh: points, cells, `material` (int32) and `local_size` (each cell's local
/// input size, size_criterion.h) cell arrays, `target` (3 components), `distance` and
/// `surface_distance` point arrays; the material names in the `materials` metadata entry.
template <class M>
io::MeshData adapt_mesh_data(const AdaptResult<M>& result,
                             const std::vector<std::string>& material_names);

}  // namespace hexadapt
