// Reading and writing mesh files by name: the format follows the extension.
//
// Read: legacy .vtk (ASCII and binary; STRUCTURED_POINTS, RECTILINEAR_GRID, STRUCTURED_GRID,
// UNSTRUCTURED_GRID), XML .vtu .vti .vtr .vts (ascii, base64, appended raw or base64, zlib,
// UInt32/UInt64 headers; zlib, LZ4 or LZMA blocks), parallel, multi-block and time-series
// files of them (.pvtu .pvts .pvtr .pvti .vtm .pvd, see vtk_collection.h), the plain text
// formats of hand-made cases (.txt, DESIGN 7.1), and Exodus II .exo .e .g (hex or quad
// elements; element variables become cell arrays; see exodus.h). The step of a time series
// (.pvd or Exodus) is chosen by ReadOptions::step or ::time.
// Write: .vtu (appended binary, zlib-compressed when large), .vts (the same, for a grid read
// from a structured data set: MeshData::structured_cells), .pvtu and .pvts (one .vtu or .vts
// piece, `<name>_0.vtu` or `<name>_0.vts`, and the parallel file naming it: what a job of one
// rank writes), legacy .vtk (binary) and
// Exodus II .exo .e .g (one element block per material, side and node sets; see exodus.h).
// Writes are atomic: a temporary file in the target directory, then a rename, so a failed
// write never leaves a half file and never clobbers an input.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io {

/// How a 2D data set is laid in the plane: `automatic` takes the flat axis of a structured
/// data set (the axis with one point) and z = constant for unstructured quads.
enum class Plane { automatic, xy, yz, xz };

struct ReadOptions {
  Plane plane = Plane::automatic;   ///< which coordinate plane 2D cells live in
  std::optional<std::size_t> step;  ///< 0-based time step to read (time series)
  std::optional<double> time;       ///< time value to read
  /// Pieces of a parallel file: points of different pieces closer than this times the
  /// shortest cell edge at them are one point.
  double weld_tolerance = 1e-6;
  /// Only the cell layers [first, end) of a structured grid across its last axis (z in 3D,
  /// the plane's second axis in 2D), with the node layers around them: what one rank of a
  /// distributed run holds. The pieces of a .pvti/.pvtr/.pvts outside them are not read; a
  /// single file is read whole, then cut. Other files are an OptionError.
  std::optional<std::array<int, 2>> layers;
};

/// A structured grid's dimension and cells per axis in the kernel's order ({nx, ny, 0} in
/// 2D, its plane mapped to xy).
struct StructuredShape {
  int dim = 0;
  std::array<int, 3> cells{0, 0, 0};
};

/// Which side sets and node sets an Exodus II file gets: the faces of the domain boundary
/// (xmin, xmax, ymin, ...), the faces between two materials, both, or none.
enum class ExodusSets { none, boundary, interfaces, all };

struct WriteOptions {
  bool compress = true;                      ///< zlib-compress .vtu data blocks
  std::size_t compress_above = 1 << 16;      ///< bytes: smaller arrays are written raw
  ExodusSets exodus_sets = ExodusSets::all;  ///< side and node sets of .exo/.e/.g files
  /// .vtu/.vts: String field-data arrays, which ParaView shows but meshio 5 refuses (it
  /// cannot read such a file): `material_names` and the exact `hexadapt_command`.
  bool string_fields = true;
};

/// "none", "boundary", "interfaces" or "all"; throws OptionError otherwise.
ExodusSets parse_exodus_sets(const std::string& text);

/// Throws InputError (malformed content, with file and place), IoError (cannot open/read).
MeshData read_mesh(const std::string& path, const ReadOptions& options = {});
/// Throws OptionError when write_mesh does not write files with path's extension, or when the
/// data to be written is not `structured` (a block of a structured grid) and the extension
/// is one of a structured grid's (.vts, .pvts).
void check_mesh_output(const std::string& path, bool structured = true);
/// Throws IoError, or OptionError for an unknown extension.
void write_mesh(const MeshData& data, const std::string& path, const WriteOptions& options = {});

/// Whether `path` holds an unstructured mesh rather than a structured grid, as far as its name
/// and, for a legacy .vtk, its DATASET line tell: .vtu .pvtu .exo .e .g, and the collections
/// that cannot be read a window of layers at a time (.vtm .pvd), do; a .vtk does when its
/// DATASET is UNSTRUCTURED_GRID. Another file, or a .vtk whose header cannot be read, does not
/// (reading it as a grid then says what is wrong).
bool holds_unstructured_mesh(const std::string& path);

/// The shape of the structured grid in `path`: a .pvti/.pvtr/.pvts is read to its header
/// only, another file whole. Throws InputError when the file holds no structured grid.
StructuredShape structured_shape(const std::string& path, const ReadOptions& options = {});

}  // namespace hexadapt::io
