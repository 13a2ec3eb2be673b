// Materials that are nowhere the majority get no cell and vanish from every later stage.
// Kept instead, each such material takes the cells where it is most present (largest
// fraction first, ties to the lowest cell id), as many as its input volume fills in cells of
// the grid's mean volume, at least one. A cell already taken for another kept material, or
// the last cell of its material, is not taken. The manifold correction runs after: a taken
// cell stays unless a non-manifold node around it makes the correction change it, which the
// final balance (material_balance.h) then shows.
#pragma once

#include <vector>

#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

struct KeptMaterial {
  int material = 0;
  index_t cells = 0;  ///< cells given to it
};

/// Gives each material with volume in `fractions` and no cell in `labels` its cells, in
/// place; one entry per material kept, in increasing material index. On ranks (`where`),
/// every rank's candidate cells are gathered and walked in one global order (cells by their
/// global id), so each rank takes what one process would, ghosts included.
template <class M>
std::vector<KeptMaterial> keep_vanished_materials(const M& mesh, const Fractions& fractions,
                                                  CellMaterials& labels,
                                                  const dist::Distribution& where);
/// The whole mesh on one process.
template <class M>
std::vector<KeptMaterial> keep_vanished_materials(const M& mesh, const Fractions& fractions,
                                                  CellMaterials& labels);

}  // namespace hexadapt::assign
