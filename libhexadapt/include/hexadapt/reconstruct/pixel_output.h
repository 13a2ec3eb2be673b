// The pixel mesh as a mesh file's content: one quad (2D) or hex (3D) per pixel with the cell
// arrays `material` (its label), `parent` (the coarse cell it was cut from) and `free` (1
// for pixels of mixed cells). Each block gets its own (nsub + 1)^d lattice points, so points
// on coarse faces appear once per block: the file is for viewing and checking, not a
// conforming mesh. Cells without pixels are not in it.
#pragma once

#include "hexadapt/dist/block.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

io::MeshData pixel_mesh_data(const PixelMesh& pixels);
/// The pixels of the cells `block` owns, `parent` naming global cells: the pieces of the ranks
/// a mesh is spread over, concatenated in rank order, are the pixels of the whole mesh.
io::MeshData pixel_mesh_data(const PixelMesh& pixels, const dist::Block& block);

/// Bytes pixel_mesh_data and a writer need per pixel (for the memory estimate).
double pixel_output_bytes_per_pixel(int dim);

}  // namespace hexadapt::reconstruct
