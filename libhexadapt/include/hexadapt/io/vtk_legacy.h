// Legacy VTK files (.vtk): read ASCII and BINARY STRUCTURED_POINTS, RECTILINEAR_GRID,
// STRUCTURED_GRID and UNSTRUCTURED_GRID (classic CELLS/CELL_TYPES and the 5.1
// OFFSETS/CONNECTIVITY layout), with CELL_DATA / POINT_DATA as SCALARS, VECTORS, NORMALS,
// TENSORS or FIELD arrays (names and element types kept; METADATA blocks and lookup tables
// skipped; bit arrays refused); write binary UNSTRUCTURED_GRID.
// Data-set level string field data becomes MeshData::metadata, as does the title line
// ("title"). Every count is checked against the bytes left before anything is allocated.
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

/// Writes a binary legacy UNSTRUCTURED_GRID (big-endian, as the format requires); the title
/// line carries the provenance metadata. Atomic. Throws IoError.
void write_vtk_legacy(const MeshData& data, const std::string& path);

}  // namespace hexadapt::io
