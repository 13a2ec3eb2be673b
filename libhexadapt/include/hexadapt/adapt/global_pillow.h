// Global pillowing of every material (base algorithm, paper Fig. 10-a, as Sculpt does): each
// material's region, in material order, is pillowed with pillow_cells(), so every interface
// gets one layer of cells on each side. The layer cells take the material of the region
// they were inflated from.
#pragma once

#include "hexadapt/adapt/pillow.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

template <class M>
struct GlobalPillowResult {
  M mesh;
  CellMaterials material;                ///< one material per output cell
  IdVector<NodeId, NodeId> node_origin;  ///< the input node each output node comes from
  IdVector<CellId, CellId> cell_origin;  ///< the input cell each output cell comes from
  index_t n_layer_cells = 0;
};

/// `material`: one index per cell of `mesh`, in [0, n_materials); `size`: the size criterion
/// on mesh's cells, which sets the layers' least thickness (off by default).
template <class M>
GlobalPillowResult<M> global_pillow(const M& mesh, const CellMaterials& material, int n_materials,
                                    const BoundaryOptions& boundary = {},
                                    const PillowOptions& options = {},
                                    const SizeCriterion& size = {});

}  // namespace hexadapt
