// Small islands (Sculpt's defeaturing): a connected piece of one material (cells sharing a
// face) of fewer than `min_cells` cells goes to a material around it, the one of those most
// present in the piece's cells (sum of their fractions; ties to the lowest index). A lone
// cell of noise, or a sliver a few cells wide, would otherwise become a tiny region of the
// output that no Lagrangian code wants.
//
// In rounds: each round finds the pieces and gives every small one to a material of the cells
// around it that are not in a small piece themselves; pieces merged that way are judged again
// in the next round. A small piece with no such neighbour (a material that is small
// everywhere and touches only other small pieces, or fills the whole grid) stays, and is
// counted in `left`. A material whose every piece is small vanishes: assign reports it.
//
// On ranks (`where`), a piece may cross rank borders: each rank finds the pieces within the
// cells it owns, and the pieces that meet across a border are joined over every rank's border
// cells. The cells of small pieces go to every rank, which sums each piece's fractions over
// its cells in increasing global id, as one process does, and relabels the cells it holds.
#pragma once

#include "hexadapt/core/ids.h"
#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

struct IslandResult {
  index_t islands = 0;  ///< pieces reassigned
  index_t cells = 0;    ///< cells reassigned
  index_t left = 0;     ///< small pieces that stay
};

/// Pieces of `labels` smaller than min_cells, reassigned in place (min_cells <= 1: none);
/// on ranks, the figures are those of the whole grid.
template <class M>
IslandResult remove_islands(const M& mesh, const Fractions& fractions, CellMaterials& labels,
                            index_t min_cells, const dist::Distribution& where);
template <class M>
IslandResult remove_islands(const M& mesh, const Fractions& fractions, CellMaterials& labels,
                            index_t min_cells);

/// The number of pieces of `labels` with fewer than min_cells cells (of the whole grid).
template <class M>
index_t count_small_pieces(const M& mesh, const CellMaterials& labels, index_t min_cells,
                           const dist::Distribution& where);
template <class M>
index_t count_small_pieces(const M& mesh, const CellMaterials& labels, index_t min_cells);

}  // namespace hexadapt::assign
