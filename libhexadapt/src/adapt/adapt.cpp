#include "hexadapt/adapt/adapt.h"

#include <optional>
#include <string>
#include <vector>

#include "base_pipeline.h"
#include "guaranteed_pipeline.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/unit_frame.h"

namespace hexadapt {

AdaptMethod parse_adapt_method(const std::string& name) {
  if (name == "base") return AdaptMethod::base;
  if (name == "guaranteed") return AdaptMethod::guaranteed;
  throw OptionError("unknown adaptation method '" + name + "' (expected base or guaranteed)");
}

std::string to_string(AdaptMethod method) {
  return method == AdaptMethod::base ? "base" : "guaranteed";
}

LayerStrategy parse_layer_strategy(const std::string& name) {
  for (LayerStrategy s : {LayerStrategy::automatic, LayerStrategy::cavities, LayerStrategy::first,
                          LayerStrategy::both})
    if (name == to_string(s)) return s;
  throw OptionError("unknown layer strategy '" + name +
                    "' (expected automatic, cavities, first or both)");
}

std::string to_string(LayerStrategy strategy) {
  switch (strategy) {
    case LayerStrategy::automatic:
      return "automatic";
    case LayerStrategy::cavities:
      return "cavities";
    case LayerStrategy::first:
      return "first";
    case LayerStrategy::both:
      return "both";
  }
  return "automatic";
}

namespace {

void check_options(const AdaptOptions& o) {
  if (!(o.threshold > -1 && o.threshold <= 1))
    throw OptionError("{threshold} must be in (-1, 1], got " + std::to_string(o.threshold));
  if (!(o.min_edge >= 0 && o.min_edge < 1))
    throw OptionError("{min_edge} must be in [0, 1), got " + std::to_string(o.min_edge));
  if (o.move.steps < 1)
    throw OptionError("{move.steps} must be at least 1, got " + std::to_string(o.move.steps));
  if (o.max_loops < 0)
    throw OptionError("{max_loops} must be >= 0, got " + std::to_string(o.max_loops));
  if (o.cavity.range < 0)
    throw OptionError("{cavity.range} must be >= 0, got " + std::to_string(o.cavity.range));
  if (o.interface_pillow.rounds < 0 || o.interface_pillow.carve < 0 || o.mend_rounds < 0)
    throw OptionError(
        "{interface_pillow.rounds}, {interface_pillow.carve} and {mend_rounds} "
        "must be >= 0");
  if (!(o.enough_share >= 0 && o.enough_share <= 1))
    throw OptionError("{enough_share} must be in [0, 1], got " + std::to_string(o.enough_share));
  if (!(o.near_interface >= 0))
    throw OptionError("{near_interface} must be >= 0, got " + std::to_string(o.near_interface));
  if (o.reach.passes < 0)
    throw OptionError("{reach.passes} must be >= 0, got " + std::to_string(o.reach.passes));
  if (!(o.loop_tolerance >= 0))
    throw OptionError("loop_tolerance must be >= 0, got " + std::to_string(o.loop_tolerance));
  if (!(o.loop_min_move >= 0))
    throw OptionError("loop_min_move must be >= 0, got " + std::to_string(o.loop_min_move));
  if (o.targets.volume_sweeps < 0 || !(o.targets.volume_max_shift >= 0) ||
      !(o.targets.volume_tolerance >= 0))
    throw OptionError("volume_sweeps, volume_max_shift and volume_tolerance must be >= 0");
  check_options(o.correction);
  if (o.method == AdaptMethod::base && !o.boundary.frozen.empty())
    throw OptionError("frozen nodes are held by the guaranteed method only");
}

// The model's facets must name materials of the fractions.
void check_model(const reconstruct::InterfaceModel* model, int dim, int n_materials) {
  if (!model) return;
  if (model->dim != dim)
    throw InputError(
        "", "model",
        "a " + std::to_string(model->dim) + "D model for a " + std::to_string(dim) + "D grid");
  for (std::size_t f = 0; f < model->facet_materials.size(); ++f)
    for (int m : model->facet_materials[f])
      if (m < 0 || m >= n_materials)
        throw InputError("", "model facet " + std::to_string(f),
                         "material index " + std::to_string(m) + " out of [0, " +
                             std::to_string(n_materials) + ")");
}

// Given targets: one per node, for the guaranteed method.
void check_targets(const Targets* targets, index_t n_nodes, AdaptMethod method) {
  if (!targets) return;
  if (method != AdaptMethod::guaranteed)
    throw OptionError("given targets are taken by the guaranteed method only");
  const auto n = static_cast<std::size_t>(n_nodes);
  if (targets->has.size() != n || targets->position.size() != n || targets->interface.size() != n)
    throw OptionError("the given targets are for " + std::to_string(targets->has.size()) +
                      " nodes, the grid has " + std::to_string(n_nodes));
}

// Every length of the result from the frame the pipeline ran in back to the grid's.
template <class M>
void result_to_world(AdaptResult<M>& r, const UnitFrame& f) {
  r.mesh = to_world(r.mesh, f);
  for (Vec3& t : r.target.raw()) t = f.to_world(t);
  for (IdVector<NodeId, double>* d : {&r.distance, &r.surface_distance})
    for (double& x : d->raw()) x = f.to_world(x);
  for (double& x : r.local_size.raw()) x = f.to_world(x);
  for (double* x : {&r.surface_dist_init, &r.surface_dist_final, &r.farthest_distance,
                    &r.farthest_local_size, &r.dist_init, &r.dist_final,
                    &r.correction.mean_displacement, &r.correction.max_displacement})
    *x = f.to_world(*x);
  for (CellFailure& c : r.failures) {
    c.shortest_edge = f.to_world(c.shortest_edge);
    c.min_length = f.to_world(c.min_length);
    c.centroid = f.to_world(c.centroid);
  }
}

template <class M>
AdaptResult<M> run_pipeline(const M& grid, const Fractions& fractions,
                            const CellMaterials& material, const AdaptOptions& options,
                            const reconstruct::InterfaceModel* model,
                            std::optional<Targets> targets) {
  switch (options.method) {
    case AdaptMethod::base:
      return detail::run_base_pipeline(grid, fractions, material, options);
    case AdaptMethod::guaranteed:
      return detail::run_guaranteed_pipeline(grid, fractions, material, options, model,
                                             std::move(targets));
  }
  throw InternalError("unhandled adaptation method");
}

// adapt() on `local`, the grid in `frame` (mesh/unit_frame.h): the pipeline runs there, its
// result goes back to the grid's frame.
template <class M>
AdaptResult<M> adapt_in_frame(const M& local, const UnitFrame& frame, const Fractions& fractions,
                              const CellMaterials& material, const AdaptOptions& options,
                              const reconstruct::InterfaceModel* model, const Targets* targets) {
  check_options(options);
  check_model(model, M::dim, fractions.n_materials());
  const std::size_t frozen = options.boundary.frozen.size();
  if (frozen != 0 && frozen != static_cast<std::size_t>(local.n_nodes()))
    throw OptionError("the frozen-node mask (BoundaryOptions::frozen) has " +
                      std::to_string(frozen) + " flags for a grid of " +
                      std::to_string(local.n_nodes()) + " nodes");
  check_targets(targets, local.n_nodes(), options.method);
  std::optional<reconstruct::InterfaceModel> local_model;
  if (model) {
    local_model = *model;
    for (Vec3& p : local_model->points) p = frame.to_local(p);
  }
  std::optional<Targets> local_targets;
  if (targets) {
    local_targets = *targets;
    for (Vec3& p : local_targets->position.raw()) p = frame.to_local(p);
    for (InterfaceFace& f : local_targets->faces) f.point = frame.to_local(f.point);
  }
  AdaptResult<M> r = run_pipeline(local, fractions, material, options,
                                  local_model ? &*local_model : nullptr, std::move(local_targets));
  result_to_world(r, frame);
  return r;
}

}  // namespace

template <class M>
AdaptResult<M> adapt(const M& grid, const Fractions& fractions, const CellMaterials& material,
                     const AdaptOptions& options, const reconstruct::InterfaceModel* model,
                     const Targets* targets) {
  const UnitFrame frame = unit_frame(grid);
  if (frame.is_identity())
    return adapt_in_frame(grid, frame, fractions, material, options, model, targets);
  return adapt_in_frame(to_local(grid, frame), frame, fractions, material, options, model, targets);
}

template AdaptResult<QuadMesh> adapt<QuadMesh>(const QuadMesh&, const Fractions&,
                                               const IdVector<CellId, int>&, const AdaptOptions&,
                                               const reconstruct::InterfaceModel*, const Targets*);
template AdaptResult<HexMesh> adapt<HexMesh>(const HexMesh&, const Fractions&,
                                             const IdVector<CellId, int>&, const AdaptOptions&,
                                             const reconstruct::InterfaceModel*, const Targets*);

AnyAdaptResult adapt(const AssignedGrid& grid, const AdaptOptions& options,
                     const reconstruct::InterfaceModel* model, const Targets* targets) {
  grid.require_assigned("adapt");
  return std::visit(
      [&](const auto& m) -> AnyAdaptResult {
        return adapt(m, grid.fractions, grid.material, options, model, targets);
      },
      grid.mesh);
}

AnyAdaptResult adapt(AssignedGrid&& grid, const AdaptOptions& options,
                     const reconstruct::InterfaceModel* model, const Targets* targets) {
  grid.require_assigned("adapt");
  return std::visit(
      [&](auto& m) -> AnyAdaptResult {
        const UnitFrame frame = unit_frame(m);
        for (NodeId v : id_range<NodeId>(m.n_nodes())) m.set_point(v, frame.to_local(m.point(v)));
        return adapt_in_frame(m, frame, grid.fractions, grid.material, options, model, targets);
      },
      grid.mesh);
}

}  // namespace hexadapt
