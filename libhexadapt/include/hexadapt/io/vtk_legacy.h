// Legacy VTK files (.vtk): read ASCII and BINARY STRUCTURED_POINTS, RECTILINEAR_GRID,
// STRUCTURED_GRID and UNSTRUCTURED_GRID (classic CELLS/CELL_TYPES and the 5.1
// OFFSETS/CONNECTIVITY layout), with CELL_DATA / POINT_DATA as SCALARS, VECTORS, NORMALS,
// TENSORS or FIELD arrays (names and element types kept; METADATA blocks and lookup tables
// skipped; bit arrays refused); write binary UNSTRUCTURED_GRID.
// Data-set level string field data becomes MeshData::metadata, as do the title line
// ("title") and our `hexadapt_command` char array. Every count is checked against the bytes left before anything is allocated.
#pragma once

#include <string>
#include <string_view>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io {

/// Parses a whole legacy VTK file held in memory; `file` names it in error messages.
/// Errors name the line (ASCII parts) or the byte offset (binary parts). Throws InputError.
MeshData read_vtk_legacy(std::string_view content, const std::string& file,
                         const ReadOptions& options = {});

/// Writes a binary legacy UNSTRUCTURED_GRID (big-endian, as the format requires). The title
/// line carries the metadata as "key=value" pairs, this file's own provenance first (from the
/// last `hexadapt_tool` entry on), as many whole pairs as its 255 characters hold, ending with
/// "; ... N more" when N were left out. The last `hexadapt_command` entry, the command exactly
/// as typed, is also kept whole as a char array `hexadapt_command` in the data set's FIELD
/// (VTK: vtkCharArray; meshio: int8 field data; read back here as that metadata entry).
/// Atomic. Throws IoError.
void write_vtk_legacy(const MeshData& data, const std::string& path);

}  // namespace hexadapt::io
