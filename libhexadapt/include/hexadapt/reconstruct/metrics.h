// The two measures of a pixel assignment (paper sec. 4.1), computed for every method.
//
// edgecut: the number of pairs of adjacent pixels assigned to different materials (a
// discrete interface length or area: lower is smoother). discrepancy: the sum over
// pixelated coarse cells cc and materials k of |volume of the pixels of cc assigned to k -
// ma_k(cc) Vol(cc)| (how far the pixels are from the volume fractions; 0 is a perfect fit).
// Both reduce in a fixed order (discrepancy exactly), so they depend neither on the thread
// count nor on the ranks a mesh is spread over.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

std::int64_t edgecut(const PixelMesh& pixels);
/// The edgecut of the whole mesh spread over ranks: each rank counts the pairs whose lower
/// pixel lies in a cell it owns (the ghost pixels next to them assigned as by their owner).
std::int64_t edgecut(const PixelMesh& pixels, const dist::Distribution& where);

/// Per block (coarse cell of the pixel mesh) discrepancy; unassigned pixels count for no
/// material.
std::vector<double> block_discrepancy(const PixelMesh& pixels, const Fractions& fractions);

/// The exact sum of block_discrepancy, rounded once.
double discrepancy(const PixelMesh& pixels, const Fractions& fractions);
/// The same over the blocks of the cells every rank owns.
double discrepancy(const PixelMesh& pixels, const Fractions& fractions,
                   const dist::Distribution& where);

/// Per block and material: the largest-remainder rounding of ma_k(cc) * nsub^d, so the
/// counts of a block sum to nsub^d exactly. Row-major, n_materials per block.
std::vector<int> largest_remainder_counts(const PixelMesh& pixels, const Fractions& fractions,
                                          index_t block);

}  // namespace hexadapt::reconstruct
