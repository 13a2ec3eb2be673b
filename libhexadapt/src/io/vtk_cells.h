// Private to the readers: building MeshData cells from VTK's structured and unstructured
// descriptions, shared by the legacy and the XML readers.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io::detail {

/// VTK cell type ids the readers accept.
enum VtkCellType : int { vtk_pixel = 8, vtk_quad = 9, vtk_voxel = 11, vtk_hexahedron = 12 };

/// Points and cells of a structured data set with dims[0] x dims[1] x dims[2] points (i
/// fastest). One axis with a single point makes it 2D (quads in the two other axes, mapped
/// to the xy plane); more than one, or an axis with no point, is an InputError, and so is a
/// NaN or infinite coordinate (naming the point).
void fill_structured(MeshData& data, std::array<std::int64_t, 3> dims, std::vector<Vec3> points,
                     const ReadOptions& options, const std::string& file);

/// Appends cell `cell` of VTK type `type` with node ids `ids`. Throws InputError (naming the
/// cell) for other cell types, a wrong number of nodes, node ids out of [0, n_points), or a
/// cell whose dimension differs from the cells before it.
void append_vtk_cell(MeshData& data, int type, const std::int64_t* ids, std::size_t n_ids,
                     std::int64_t cell, const std::string& file);

/// After all cells of an unstructured 2D set are read: puts the quads in the xy plane
/// (options.plane, or the coordinate plane they lie in) and makes them counter-clockwise
/// when the file lists them clockwise. Throws InputError when the quads are not planar.
void finish_unstructured(MeshData& data, const ReadOptions& options, const std::string& file);

}  // namespace hexadapt::io::detail
