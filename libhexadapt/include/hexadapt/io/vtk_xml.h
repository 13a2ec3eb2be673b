// VTK XML files: read .vtu .vti .vtr .vts, write .vtu and .vts (VTK file format spec,
// "XML File Formats").
//
// Reading accepts every encoding VTK, ParaView and meshio write: ascii, inline base64,
// appended raw or base64, zlib-compressed blocks, UInt32 or UInt64 headers, either byte
// order. The XML structure is parsed by pugixml; raw appended data (not XML) is located by
// its offset and decoded directly, so large files read at disk and zlib speed.
#pragma once

#include <string>
#include <string_view>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io {

/// Parses a whole XML VTK file held in memory; `file` names it in error messages. The data
/// set type is taken from the VTKFile element. Throws InputError.
MeshData read_vtk_xml(std::string_view content, const std::string& file,
                      const ReadOptions& options = {});

/// Writes an UnstructuredGrid (.vtu): appended binary data, zlib-compressed per options,
/// metadata as string field data. Atomic. Throws IoError.
void write_vtu(const MeshData& data, const std::string& path, const WriteOptions& options = {});

/// Writes a StructuredGrid (.vts); needs data.structured_cells (a structured source).
/// Throws OptionError when the data is not structured, IoError on write failure.
void write_vts(const MeshData& data, const std::string& path, const WriteOptions& options = {});

}  // namespace hexadapt::io
