// Each material's volume before and after the assignment: the input volume its fractions
// give (sum over cells of fraction x cell volume) and the volume of the cells assigned to
// it. A material that is nowhere the majority gets no cell at all and vanishes from every
// later stage; this is how the stage says so.
#pragma once

#include <vector>

#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

struct MaterialBalance {
  double input_volume = 0;     ///< sum_c fraction(c) x V(c)
  double assigned_volume = 0;  ///< sum of V(c) over the cells assigned to the material
  index_t assigned_cells = 0;
  double input_share = 0;  ///< input_volume / the domain's volume
  /// The material had volume in the input and has no cell now.
  bool vanished() const { return input_volume > 0 && assigned_cells == 0; }
};

/// One entry per material of `fractions`, for the assignment `labels` of mesh's cells.
template <class M>
std::vector<MaterialBalance> material_balance(const M& mesh, const Fractions& fractions,
                                              const CellMaterials& labels);

/// The same over the cells one rank owns, summed per rank, then in rank order.
template <class M>
std::vector<MaterialBalance> material_balance(const M& mesh, const Fractions& fractions,
                                              const CellMaterials& labels,
                                              const dist::Distribution& where);

}  // namespace hexadapt::assign
