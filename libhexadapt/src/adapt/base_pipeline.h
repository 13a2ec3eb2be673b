// The base pipeline (paper Fig. 10-a), internal: adapt() dispatches to it.
#pragma once

#include "hexadapt/adapt/adapt.h"

namespace hexadapt::detail {

/// Targets, direct move, global pillowing of every material, global smoothing.
template <class M>
AdaptResult<M> run_base_pipeline(const M& grid, const Fractions& fractions,
                                 const CellMaterials& material, const AdaptOptions& options);

}  // namespace hexadapt::detail
