// Private to the writers: the material names of a mesh file's data, from the `materials`
// metadata entry (comma-separated, in material index order; adapt_io.h writes it) or the
// `hexadapt_materials` one (assign and reconstruct).
#pragma once

#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io::detail {

/// The names of the last `materials` entry, else of the last `hexadapt_materials` entry;
/// empty when there is none.
std::vector<std::string> material_names(const MeshData& data);

}  // namespace hexadapt::io::detail
