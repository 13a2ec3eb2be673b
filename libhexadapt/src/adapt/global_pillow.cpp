#include "hexadapt/adapt/global_pillow.h"

#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt {

template <class M>
GlobalPillowResult<M> global_pillow(const M& mesh, const CellMaterials& material, int n_materials,
                                    const BoundaryOptions& boundary, const PillowOptions& options,
                                    const SizeCriterion& size) {
  if (material.size() != static_cast<std::size_t>(mesh.n_cells()))
    throw InternalError("global pillow: materials do not match the mesh's cells");
  GlobalPillowResult<M> out;
  out.mesh = mesh;
  out.material = material;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) out.node_origin.push_back(v);
  for (CellId c : id_range<CellId>(mesh.n_cells())) out.cell_origin.push_back(c);
  for (int m = 0; m < n_materials; ++m) {
    IdVector<CellId, char> in_set(static_cast<std::size_t>(out.mesh.n_cells()), 0);
    bool any = false;
    for (CellId c : id_range<CellId>(out.mesh.n_cells())) {
      in_set[c] = out.material[c] == m;
      any = any || in_set[c];
    }
    if (!any) continue;
    PillowResult<M> p = pillow_cells(out.mesh, in_set, boundary_constraints(out.mesh, boundary),
                                     options, size.remapped(out.cell_origin.raw()));
    if (p.n_new_cells == 0) continue;
    // Compose the maps: new items point through the step's origin to the input.
    for (NodeId v : id_range<NodeId>(p.mesh.n_nodes()))
      if (v.value() >= out.mesh.n_nodes())
        out.node_origin.push_back(out.node_origin[p.node_origin[v]]);
    for (CellId c : id_range<CellId>(p.mesh.n_cells()))
      if (c.value() >= out.mesh.n_cells()) {
        out.cell_origin.push_back(out.cell_origin[p.cell_origin[c]]);
        out.material.push_back(m);
      }
    out.n_layer_cells += p.n_new_cells;
    out.mesh = std::move(p.mesh);
  }
  return out;
}

template GlobalPillowResult<QuadMesh> global_pillow<QuadMesh>(const QuadMesh&,
                                                              const IdVector<CellId, int>&, int,
                                                              const BoundaryOptions&,
                                                              const PillowOptions&,
                                                              const SizeCriterion&);
template GlobalPillowResult<HexMesh> global_pillow<HexMesh>(const HexMesh&,
                                                            const IdVector<CellId, int>&, int,
                                                            const BoundaryOptions&,
                                                            const PillowOptions&,
                                                            const SizeCriterion&);

}  // namespace hexadapt
