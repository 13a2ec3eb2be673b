// Private to the readers and writers: the command that made a file. The tools record it as
// the metadata entry `hexadapt_command`, after the entries of the files they read, so the
// last one is this file's own. The writers keep it exact (as typed, ready to paste back into
// a shell) where the format allows: a String field-data array in .vtu/.vts, a char array in
// the data-set FIELD of a legacy .vtk (whose title line holds 255 characters only). There,
// a second char array, `hexadapt_metadata`, holds every entry as the .vtu's comment does
// (vtk_xml_comment.h), which the reader takes back whole.
#pragma once

#include <string>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io::detail {

inline constexpr const char* command_key = "hexadapt_command";
inline constexpr const char* metadata_key = "hexadapt_metadata";

/// The last `hexadapt_command` entry of the metadata, or nullptr when there is none.
const std::string* last_command(const MeshData& data);

}  // namespace hexadapt::io::detail
