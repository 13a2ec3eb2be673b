// Simulated annealing of the sub-pixel assignment (paper sec. 4.1.2, Algorithm 3, after
// VisIt's discrete interface reconstruction).
//
// Start: each mixed cell's pixels receive the largest-remainder rounding of its fractions
// (so counts sum to nsub^d), placed in a seeded random order. Moves: swap two differently
// labelled pixels of one randomly drawn mixed cell (ten draws to find such a pair). Energy of
// a pixel: the sum over its neighbours with another label of 1 / distance between centres,
// distances in units of the mean pixel width. Metropolis acceptance: a swap that lowers the
// energy is taken, otherwise with probability exp(-dE / T), T cooling geometrically from
// t_start to t_end over the run. Swaps keep every cell's pixel counts, so on equal pixels
// the fractions stay matched; on unstructured cells pixel volumes differ and they do not
// (the paper's Fig. 8).
//
// Reproducibility: with an iteration count, the result depends only on the input and the
// seed, whatever the thread count (the moves run on one thread). With a time budget the
// number of moves depends on the machine's speed, so results differ from run to run.
#pragma once

#include <cstdint>

#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

struct AnnealingOptions {
  std::int64_t iterations = 0;  ///< swap attempts; 0: 200 per free pixel
  double time_budget = 0;       ///< seconds; > 0 runs until then instead (not reproducible)
  std::uint64_t seed = 1;       ///< random seed of the fill and the moves
  double t_start = 0.25;        ///< initial temperature (the paper's constant T)
  double t_end = 0.01;          ///< final temperature of the geometric cooling
  int swap_tries = 10;          ///< draws to find two differently labelled pixels of a cell
};

struct AnnealingResult {
  std::int64_t attempts = 0;    ///< moves tried
  std::int64_t accepted = 0;    ///< swaps made
  std::int64_t initial_edgecut = 0;  ///< edgecut of the initial fill
  double initial_energy = 0, final_energy = 0;
  bool time_limited = false;    ///< ran on the time budget
};

/// Fills the free pixels with largest-remainder counts in a seeded random order.
void largest_remainder_fill(PixelMesh& pixels, const Fractions& fractions, std::uint64_t seed);

/// Fills the free pixels then anneals them.
AnnealingResult annealing_assign(PixelMesh& pixels, const Fractions& fractions,
                                 const AnnealingOptions& options = {});

/// Total energy: the sum over adjacent pairs with different labels of 1 / distance.
double pair_energy(const PixelMesh& pixels);

}  // namespace hexadapt::reconstruct
