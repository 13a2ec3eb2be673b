// The two measures of a pixel assignment (paper sec. 4.1), computed for every method.
//
// edgecut: the number of pairs of adjacent pixels assigned to different materials (a
// discrete interface length or area: lower is smoother). discrepancy: the sum over
// pixelated coarse cells cc and materials k of |volume of the pixels of cc assigned to k -
// ma_k(cc) Vol(cc)| (how far the pixels are from the volume fractions; 0 is a perfect fit).
// Both reduce in a fixed order, so they do not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

std::int64_t edgecut(const PixelMesh& pixels);

/// Per block (coarse cell of the pixel mesh) discrepancy; unassigned pixels count for no
/// material.
std::vector<double> block_discrepancy(const PixelMesh& pixels, const Fractions& fractions);

/// Sum of block_discrepancy.
double discrepancy(const PixelMesh& pixels, const Fractions& fractions);

/// Per block and material: the largest-remainder rounding of ma_k(cc) * nsub^d, so the
/// counts of a block sum to nsub^d exactly. Row-major, n_materials per block.
std::vector<int> largest_remainder_counts(const PixelMesh& pixels, const Fractions& fractions,
                                          index_t block);

}  // namespace hexadapt::reconstruct
