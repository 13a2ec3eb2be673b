// VTK XML files: read .vtu .vti .vtr .vts, write .vtu and .vts and the parallel files that
// name such pieces, .pvtu and .pvts (VTK file format spec, "XML File Formats").
//
// Reading accepts every encoding VTK, ParaView and meshio write: ascii, inline base64,
// appended raw or base64, zlib-, LZ4- or LZMA-compressed blocks (vtkZLibDataCompressor,
// vtkLZ4DataCompressor, vtkLZMADataCompressor), UInt32 or UInt64 headers, either byte
// order. The XML structure is parsed by pugixml; raw appended data (not XML) is located by
// its offset and decoded directly, so large files read at disk and zlib speed.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io {

// Metadata comment. MeshData::metadata is written as one XML comment between the XML
// declaration and <VTKFile> (String field data would stop meshio 5 from reading the file):
//
//   <!-- hexadapt metadata
//   tool: hexadapt-overlay
//   command: hexadapt-overlay in.vtu -\x2Dthreads 2
//   -->
//
// The first line is the title "hexadapt metadata", then one "key: value" line per entry, in
// order; the key ends at the first ": " of the line. Keys and values are escaped so the
// comment is valid XML and the lines split back exactly:
//   \\    a backslash
//   \n    a line break (LF)
//   \xHH  the byte with hexadecimal value HH, used for: a '-' that follows another '-' or
//         ends the key or value ("--" and a final '-' are not allowed in a comment); '<'
//         (so that text searches for "<AppendedData", as meshio's, never match inside the
//         comment); control characters but tab (CR included) and DEL; bytes that are not
//         valid UTF-8; ':' in keys.
// Everything else, '&' and '>' included, is written as it is. The reader accepts the comment
// before <VTKFile> or as a child of it.
//
// String field data. When the metadata names the materials (`materials` or
// `hexadapt_materials`, comma-separated), they are also written as a String field-data array
// `material_names`, one string per material index, so that ParaView shows them next to the
// `material` index array. The last `hexadapt_command` entry (the command that made the file;
// the comment escapes its "--") is written exactly as a String array `hexadapt_command`, one
// string, which ParaView shows and a user can paste back into a shell. meshio 5 refuses
// String arrays (it cannot read such a file): WriteOptions::string_fields = false leaves both
// out. The reader returns String field-data arrays as metadata entries, one line per string,
// except `hexadapt_command` when the file has our comment (the comment holds it already).

/// Parses a whole XML VTK file held in memory; `file` names it in error messages. The data
/// set type is taken from the VTKFile element; a file must hold one Piece. Cells: quads,
/// pixels, hexahedra, voxels (see mesh_data.h for the order). Arrays keep their name, type
/// and component count. Metadata: the entries of our metadata comment (see below), then the
/// String arrays of FieldData (several strings of one array joined by newlines). Throws InputError
/// naming the file, the place (element, byte offset, cell) and what was expected.
MeshData read_vtk_xml(std::string_view content, const std::string& file,
                      const ReadOptions& options = {});

/// Writes an UnstructuredGrid (.vtu): raw appended data with UInt64 headers; points as
/// Float64, connectivity and offsets as Int64 in VTK's node order (VTK_HEXAHEDRON or
/// VTK_QUAD), arrays with their own type, metadata as a comment (see below). Compression: the
/// file is zlib-compressed when options.compress is set and some array is larger than
/// options.compress_above bytes; VTK's format compresses all arrays of a file or none, so
/// the smaller arrays of such a file are stored in zlib blocks at level 0 (not compressed).
/// The bytes do not depend on the thread count. Atomic. Throws OptionError (no cells, an
/// array of the wrong size), IoError.
void write_vtu(const MeshData& data, const std::string& path, const WriteOptions& options = {});

/// Writes a StructuredGrid (.vts) like write_vtu; needs data.structured_cells with cells
/// exactly those of that block (a structured source). `origin`: the index of the block's
/// first cell per axis in a larger grid whose piece it is (its Extent starts there). Throws
/// OptionError when the data is not structured, IoError on write failure.
void write_vts(const MeshData& data, const std::string& path, const WriteOptions& options = {},
               const std::array<int, 3>& origin = {0, 0, 0});

/// Writes the parallel file (.pvtu) that names `pieces` (.vtu files, relative to its folder)
/// as one unstructured grid, declaring the point and cell arrays of `layout` (one piece's
/// data: its arrays' names, types and components, and the metadata). Atomic. Throws
/// OptionError (no cells in layout), IoError.
void write_pvtu(const MeshData& layout, const std::vector<std::string>& pieces,
                const std::string& path);

/// A piece of a .pvts: its .vts file (relative to the .pvts's folder), the index of its first
/// cell per axis in the whole grid, and its cells per axis.
struct StructuredPiece {
  std::string file;
  std::array<int, 3> origin{0, 0, 0};
  std::array<int, 3> cells{0, 0, 0};
};

/// Writes the parallel file (.pvts) of a structured grid of `whole_cells` cells per axis made
/// of `pieces` (written by write_vts with their origins), declaring the arrays of `layout`
/// as write_pvtu does. Atomic. Throws OptionError (no cells in layout), IoError.
void write_pvts(const MeshData& layout, const std::array<int, 3>& whole_cells,
                const std::vector<StructuredPiece>& pieces, const std::string& path);

/// The file of piece `piece` of the parallel file `parallel`: `<parallel without its
/// extension>_<piece>.vts` for a .pvts, `.vtu` otherwise.
std::string piece_path(const std::string& parallel, int piece);

}  // namespace hexadapt::io
