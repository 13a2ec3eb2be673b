// Private to the legacy VTK reader: the attribute sections (CELL_DATA, POINT_DATA) and FIELD
// blocks that follow the geometry of a data set.
#pragma once

#include "hexadapt/io/legacy_scanner.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io::detail {

/// Reads from a CELL_DATA or POINT_DATA keyword to the end of the file into data's arrays.
/// SCALARS (1-4 components, with or without LOOKUP_TABLE), VECTORS, NORMALS, TENSORS,
/// TEXTURE_COORDINATES, GLOBAL_IDS, PEDIGREE_IDS, COLOR_SCALARS and FIELD arrays keep their
/// names and types; LOOKUP_TABLE sections and METADATA blocks are skipped.
void read_attributes(LegacyScanner& s, MeshData& data);

/// Reads a data-set level FIELD block (the FIELD keyword already read): string arrays become
/// metadata (name, first value), and so does our `hexadapt_command` char array (its bytes);
/// our `hexadapt_metadata` char array gives every entry back (then the title line and the
/// command array, which repeat some, are dropped); other numeric ones (e.g. a time value)
/// are checked and dropped.
void read_dataset_field(LegacyScanner& s, MeshData& data);

}  // namespace hexadapt::io::detail
