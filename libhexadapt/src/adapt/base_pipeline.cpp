// The base algorithm (paper Fig. 10-a, Sculpt-like): direct move, global pillowing, global
// smoothing. No quality guarantee: it is what the guaranteed pipeline is compared with.
#include "base_pipeline.h"

#include "pipeline_steps.h"

namespace hexadapt::detail {

template <class M>
AdaptResult<M> run_base_pipeline(const M& grid, const Fractions& fractions,
                                 const CellMaterials& material, const AdaptOptions& options) {
  AdaptResult<M> r;
  Timer clock;
  if (options.progress) options.progress("targets", 0.0);
  M mesh = grid;
  const auto boundary = boundary_constraints(mesh, options.boundary);
  const Targets targets = compute_targets(mesh, fractions, material, boundary, options.targets);
  r.n_interface_nodes = targets.n_interface_nodes;
  record_step(r, mesh, "targets", clock, options.progress, 0.1, "move");

  r.dist_init = direct_move(mesh, targets).dist;
  record_step(r, mesh, "move", clock, options.progress, 0.3, "pillow");

  const SizeCriterion size = size_criterion(grid, options.min_edge);
  GlobalPillowResult<M> p = global_pillow(mesh, material, fractions.n_materials(), options.boundary,
                                          options.pillow, size);
  record_step(r, p.mesh, "pillow", clock, options.progress, 0.6, "smooth");

  // Interface nodes sit on their targets: only the nodes the pillowing made, and the nodes
  // away from the interfaces, may move.
  const auto nn = static_cast<std::size_t>(p.mesh.n_nodes());
  IdVector<NodeId, Vec3> target(nn, Vec3::Zero());
  IdVector<NodeId, char> has(nn, 0), movable(nn, 1);
  for (NodeId v : id_range<NodeId>(p.mesh.n_nodes())) {
    if (v.value() < grid.n_nodes() && targets.has[v]) {
      target[v] = targets.position[v];
      has[v] = 1;
      movable[v] = 0;
    }
  }
  smooth(p.mesh, movable, boundary_constraints(p.mesh, options.boundary), options.smooth);
  record_step(r, p.mesh, "smooth", clock, options.progress, 1.0, "done");

  r.mesh = std::move(p.mesh);
  r.material = std::move(p.material);
  finish_result(r, target, has, size.remapped(p.cell_origin.raw()), nullptr, options);
  return r;
}

template AdaptResult<QuadMesh> run_base_pipeline<QuadMesh>(const QuadMesh&, const Fractions&,
                                                           const IdVector<CellId, int>&,
                                                           const AdaptOptions&);
template AdaptResult<HexMesh> run_base_pipeline<HexMesh>(const HexMesh&, const Fractions&,
                                                         const IdVector<CellId, int>&,
                                                         const AdaptOptions&);

}  // namespace hexadapt::detail
