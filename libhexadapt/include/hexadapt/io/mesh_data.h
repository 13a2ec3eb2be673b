// MeshData: what a mesh file holds, independent of the format it came from.
//
// Points, one kind of cell (quads for 2D, hexes for 3D), named cell and point arrays and
// provenance strings. Readers fill it, writers write it, and to_mesh / from_mesh convert to
// and from the kernels. Cells are stored in the kernels' order: quads counter-clockwise
// (as VTK_QUAD), hexes in binary lattice order (as VTK_VOXEL); the readers and writers
// convert VTK_HEXAHEDRON and VTK_PIXEL with the tables of geometry.h.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::io {

/// The element type an array had in its file (kept so that writing it back keeps it).
enum class ScalarType {
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  int64,
  uint64,
  float32,
  float64
};

struct DataArray {
  std::string name;
  int n_components = 1;
  ScalarType type = ScalarType::float64;
  std::vector<double> values;  ///< n_tuples * n_components, tuple after tuple
  std::size_t n_tuples() const {
    return n_components > 0 ? values.size() / static_cast<std::size_t>(n_components) : 0;
  }
};

struct MeshData {
  int dim = 0;  ///< 2: quads in the xy plane, 3: hexes, 0: no cells
  std::vector<Vec3> points;
  std::vector<NodeId> cells;  ///< nodes_per_cell() ids per cell, kernel order (see above)
  std::vector<DataArray> cell_data;
  std::vector<DataArray> point_data;
  /// Provenance and other key/value strings (tool, version, options). Written as an XML
  /// comment in .vtu/.vts, as key=value pairs in the legacy .vtk title line (whole pairs, as
  /// many as its 255 characters hold) and as Exodus II info records; the last
  /// `hexadapt_command` also exactly as field data in .vtu/.vts/.vtk (vtk_xml.h, vtk_legacy.h).
  std::vector<std::pair<std::string, std::string>> metadata;
  /// Cells per axis when the source was a structured data set ({0,0,0} otherwise); writers
  /// of structured formats use it, others ignore it.
  std::array<int, 3> structured_cells{0, 0, 0};

  int nodes_per_cell() const { return dim == 3 ? 8 : 4; }
  index_t n_cells() const {
    return dim == 0
               ? 0
               : static_cast<index_t>(cells.size() / static_cast<std::size_t>(nodes_per_cell()));
  }
  index_t n_points() const { return static_cast<index_t>(points.size()); }
  /// The data came from a structured data set (structured_cells set), as a .vts can hold.
  bool is_structured() const { return dim != 0 && structured_cells[0] > 0; }

  const DataArray* find_cell_array(const std::string& name) const;
  const DataArray* find_point_array(const std::string& name) const;
  /// Adds or replaces a cell (point) array; throws Error when its size does not match.
  void set_cell_array(DataArray a);
  void set_point_array(DataArray a);
  /// Throws OptionError naming `path` (the file about to be written) when an array's size
  /// does not match the points or cells it belongs to.
  void check_array_sizes(const std::string& path) const;
};

/// Cuts a structured grid's data (points, cells, arrays) to the cell layers [first, end) of
/// its last axis (z in 3D, y in 2D) and the node layers around them (ReadOptions::layers);
/// `file` names it in errors. Throws OptionError when the data is not a structured grid and
/// InputError when the layers are not inside it.
void keep_layers(MeshData& data, const std::array<int, 2>& layers, const std::string& file);

/// Builds the kernel for the data's dimension. Throws MeshError (bad topology) or
/// InputError (no cells). Node and cell ids are those of the data.
AnyMesh to_mesh(const MeshData& data);

/// to_mesh for the data read from `file`: its errors name the file ("in.vtu: cell 3 repeats
/// a node"), as every message about an input does.
AnyMesh to_mesh(const MeshData& data, const std::string& file);
/// Points and cells of a mesh (no arrays).
MeshData from_mesh(const QuadMesh& mesh);
MeshData from_mesh(const HexMesh& mesh);
MeshData from_mesh(const AnyMesh& mesh);

}  // namespace hexadapt::io
