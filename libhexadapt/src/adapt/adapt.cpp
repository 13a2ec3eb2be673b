#include "hexadapt/adapt/adapt.h"

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "base_pipeline.h"
#include "guaranteed_pipeline.h"
#include "hexadapt/core/error.h"

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
    case LayerStrategy::automatic: return "automatic";
    case LayerStrategy::cavities: return "cavities";
    case LayerStrategy::first: return "first";
    case LayerStrategy::both: return "both";
  }
  return "automatic";
}

namespace {

void check_options(const AdaptOptions& o) {
  if (!(o.threshold > -1 && o.threshold <= 1))
    throw OptionError("threshold must be in (-1, 1], got " + std::to_string(o.threshold));
  if (!(o.min_edge >= 0 && o.min_edge < 1))
    throw OptionError("min_edge must be in [0, 1), got " + std::to_string(o.min_edge));
  if (o.steps < 1) throw OptionError("steps must be at least 1, got " + std::to_string(o.steps));
  if (o.max_loops < 0)
    throw OptionError("max_loops must be >= 0, got " + std::to_string(o.max_loops));
  if (o.cavity_range < 0)
    throw OptionError("cavity_range must be >= 0, got " + std::to_string(o.cavity_range));
  if (o.interface_pillow_rounds < 0 || o.interface_pillow_carve < 0)
    throw OptionError("interface_pillow_rounds and interface_pillow_carve must be >= 0");
  if (!(o.enough_share >= 0 && o.enough_share <= 1))
    throw OptionError("enough_share must be in [0, 1], got " + std::to_string(o.enough_share));
  if (!(o.near_interface >= 0))
    throw OptionError("near_interface must be >= 0, got " + std::to_string(o.near_interface));
  if (!(o.loop_tolerance >= 0))
    throw OptionError("loop_tolerance must be >= 0, got " + std::to_string(o.loop_tolerance));
  if (o.targets.volume_sweeps < 0 || !(o.targets.volume_max_shift >= 0) ||
      !(o.targets.volume_tolerance >= 0))
    throw OptionError("volume_sweeps, volume_max_shift and volume_tolerance must be >= 0");
  check_options(o.correction);
}

// The model's facets must name materials of the fractions.
void check_model(const reconstruct::InterfaceModel* model, int dim, int n_materials) {
  if (!model) return;
  if (model->dim != dim)
    throw InputError("", "model", "a " + std::to_string(model->dim) + "D model for a " +
                                      std::to_string(dim) + "D grid");
  for (std::size_t f = 0; f < model->facet_materials.size(); ++f)
    for (int m : model->facet_materials[f])
      if (m < 0 || m >= n_materials)
        throw InputError("", "model facet " + std::to_string(f),
                         "material index " + std::to_string(m) + " out of [0, " +
                             std::to_string(n_materials) + ")");
}

// A grid farther from the origin than its own size is meshed with its lowest corner moved to
// the origin: there (cells of 0.1 at 1e6) every difference of coordinates would lose digits,
// and the grid would not mesh as the same grid at the origin does. The result is moved back.
template <class M>
M translated(const M& mesh, const Vec3& by) {
  std::vector<Vec3> points;
  std::vector<typename M::CellNodes> cells;
  points.reserve(static_cast<std::size_t>(mesh.n_nodes()));
  cells.reserve(static_cast<std::size_t>(mesh.n_cells()));
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) points.push_back(mesh.point(v) + by);
  for (CellId c : id_range<CellId>(mesh.n_cells())) cells.push_back(mesh.cell_nodes(c));
  return M(std::move(points), std::move(cells));
}

template <class M>
Vec3 local_origin(const M& mesh) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    low = low.cwiseMin(mesh.point(v));
    high = high.cwiseMax(mesh.point(v));
  }
  const bool far = mesh.n_nodes() > 0 && low.allFinite() && high.allFinite() &&
                   low.norm() > (high - low).norm();
  return far ? low : Vec3(Vec3::Zero());
}

template <class M>
void translate_result(AdaptResult<M>& r, const Vec3& by) {
  r.mesh = translated(r.mesh, by);
  for (Vec3& t : r.target.raw()) t += by;
  for (CellFailure& f : r.failures) f.centroid += by;
}

template <class M>
AdaptResult<M> run_pipeline(const M& grid, const Fractions& fractions,
                            const IdVector<CellId, int>& material, const AdaptOptions& options,
                            const reconstruct::InterfaceModel* model) {
  switch (options.method) {
    case AdaptMethod::base:
      return detail::run_base_pipeline(grid, fractions, material, options);
    case AdaptMethod::guaranteed:
      return detail::run_guaranteed_pipeline(grid, fractions, material, options, model);
  }
  throw InternalError("unhandled adaptation method");
}

}  // namespace

template <class M>
AdaptResult<M> adapt(const M& grid, const Fractions& fractions,
                     const IdVector<CellId, int>& material, const AdaptOptions& options,
                     const reconstruct::InterfaceModel* model) {
  check_options(options);
  check_model(model, M::dim, fractions.n_materials());
  const Vec3 origin = local_origin(grid);
  if (origin == Vec3::Zero()) return run_pipeline(grid, fractions, material, options, model);
  std::optional<reconstruct::InterfaceModel> local_model;
  if (model) {
    local_model = *model;
    for (Vec3& p : local_model->points) p -= origin;
  }
  AdaptResult<M> r = run_pipeline(translated(grid, Vec3(-origin)), fractions, material, options,
                                  local_model ? &*local_model : nullptr);
  translate_result(r, origin);
  return r;
}

template AdaptResult<QuadMesh> adapt<QuadMesh>(const QuadMesh&, const Fractions&,
                                               const IdVector<CellId, int>&, const AdaptOptions&,
                                               const reconstruct::InterfaceModel*);
template AdaptResult<HexMesh> adapt<HexMesh>(const HexMesh&, const Fractions&,
                                             const IdVector<CellId, int>&, const AdaptOptions&,
                                             const reconstruct::InterfaceModel*);

}  // namespace hexadapt
