// Greedy sub-pixel assignment (paper sec. 4.1.4, Algorithm 4): the default method.
//
// Each free pixel carries a vector of material fractions, initially its coarse cell's.
// Rounds repeat: a few diffusion sweeps average each free pixel's vector with its
// neighbours' (fixed pixels count as one-hot vectors) and renormalise it; each cell's free
// vectors are rescaled so that they carry the volume the cell still owes to each material;
// then every free pixel whose largest fraction reaches the threshold is fixed to that
// material, most confident first, provided the cell still owes at least half the pixel's
// volume of it. The threshold starts at 1 and decreases when a round fixes nothing (or after
// a few rounds at one level). Once it reaches 0, the remaining pixels go to the material
// owed most. With equal pixel volumes this keeps every cell's material volumes within one
// pixel of its fractions; on unstructured cells the volume bookkeeping still holds.
// Deterministic: Jacobi sweeps, per-cell decisions, fixed orders.
#pragma once

#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

struct GreedyOptions {
  double threshold_step = 0.1;  ///< how much the threshold drops when a round fixes nothing
  int rounds_per_threshold = 3;  ///< rounds at one threshold level before it drops anyway
  int diffusion_sweeps = 3;      ///< neighbour-averaging sweeps per round
};

struct GreedyResult {
  int rounds = 0;              ///< rounds run
  std::int64_t fallback_pixels = 0;  ///< pixels placed by the final "owed most" pass
};

/// Assigns every free pixel. Working memory: two fraction vectors and the neighbour ids of
/// every free pixel.
GreedyResult greedy_assign(PixelMesh& pixels, const Fractions& fractions,
                           const GreedyOptions& options = {});

/// The same on the part of a mesh one rank holds (`where.block`, in the ids of the cells the
/// pixels were built on): every rank assigns the free blocks it holds, and after each round
/// the ghost blocks take their owner's state, so the owned blocks end as on one rank holding
/// the whole mesh, given greedy_ghost_layers() layers of ghost cells around them. Counts are
/// of the whole mesh. Every rank calls it.
GreedyResult greedy_assign(PixelMesh& pixels, const Fractions& fractions,
                           const GreedyOptions& options, const dist::Distribution& where);

/// The layers of ghost cells greedy_assign on ranks needs around the owned cells, for pixels of
/// nsub per axis: one more than the cells a round's diffusion reaches into, and at least two
/// (a cell's pixels depend on its neighbours' neighbours).
int greedy_ghost_layers(int nsub, const GreedyOptions& options);

/// Bytes greedy_assign needs per free pixel with n_materials materials.
double greedy_bytes_per_free_pixel(int n_materials, int dim);

}  // namespace hexadapt::reconstruct
