// The guaranteed-quality pipeline (paper Fig. 10-b), internal: adapt() dispatches to it.
#pragma once

#include <optional>

#include "hexadapt/adapt/adapt.h"

namespace hexadapt::detail {

/// Input check, targets, (3D, with a model) target correction, controlled move, cavities,
/// move-smooth loop; every output cell >= threshold when every input cell is. `targets`: the
/// given targets (adapt()'s), taken over; none: computed on the grid.
template <class M>
AdaptResult<M> run_guaranteed_pipeline(const M& grid, const Fractions& fractions,
                                       const CellMaterials& material, const AdaptOptions& options,
                                       const reconstruct::InterfaceModel* model,
                                       std::optional<Targets> targets);

}  // namespace hexadapt::detail
