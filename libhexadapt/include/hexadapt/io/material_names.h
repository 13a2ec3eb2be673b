// The material names a mesh file keeps: one metadata entry, `hexadapt_materials`, that every
// stage writes (the names in material index order, joined by join_material_names), and the
// one reader of them, which also takes what older files and other writers left.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io {

/// The metadata key of the names.
inline constexpr const char* material_names_key = "hexadapt_materials";

/// Material names as one metadata value: separated by commas, a comma or backslash inside a
/// name preceded by a backslash. split_material_names reads it back.
std::string join_material_names(const std::vector<std::string>& names);
std::vector<std::string> split_material_names(const std::string& joined);

/// Sets the names entry of `data`, replacing any earlier one.
void set_material_names(MeshData& data, const std::vector<std::string>& names);

/// The names `data` keeps: the last `hexadapt_materials` entry; else the last `materials`
/// entry (the key of earlier adapt outputs); else the `material_names` String field-data
/// array, one name per line, as the VTK XML writer adds it and a reader finds it in a file
/// saved again by ParaView. Empty when there is none.
std::vector<std::string> material_names(const MeshData& data);

}  // namespace hexadapt::io
