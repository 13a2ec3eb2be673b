#include "hexadapt/adapt/adapt.h"

#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/core/timer.h"

namespace hexadapt {

AdaptMethod parse_adapt_method(const std::string& name) {
  if (name == "base") return AdaptMethod::base;
  if (name == "guaranteed") return AdaptMethod::guaranteed;
  throw OptionError("unknown adaptation method '" + name + "' (expected base or guaranteed)");
}

std::string to_string(AdaptMethod method) {
  return method == AdaptMethod::base ? "base" : "guaranteed";
}

namespace {

void check_options(const AdaptOptions& o) {
  if (!(o.threshold > -1 && o.threshold <= 1))
    throw OptionError("threshold must be in (-1, 1], got " + std::to_string(o.threshold));
  if (o.steps < 1) throw OptionError("steps must be at least 1, got " + std::to_string(o.steps));
  if (o.method == AdaptMethod::guaranteed)
    throw OptionError("the guaranteed method is not implemented yet; use --method base");
}

// Records a finished step and restarts the step clock.
template <class M>
void record(AdaptResult<M>& r, const M& mesh, const std::string& name, Timer& clock,
            const Progress& progress, double done) {
  r.steps.push_back({name, min_quality(mesh), mesh.n_cells(), clock.seconds()});
  clock.restart();
  if (progress) progress("adapt", done);
}

template <class M>
void finish(AdaptResult<M>& r, const IdVector<NodeId, Vec3>& target,
            const IdVector<NodeId, char>& has, const AdaptOptions& options) {
  const M& mesh = r.mesh;
  r.target = target;
  r.has_target = has;
  r.distance.assign(static_cast<std::size_t>(mesh.n_nodes()), 0.0);
  r.dist_final = 0;
  r.n_reached = 0;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (!has[v]) {
      r.target[v] = mesh.point(v);
      continue;
    }
    r.distance[v] = (mesh.point(v) - target[v]).norm();
    r.dist_final += r.distance[v];
    r.n_reached += r.distance[v] == 0;
  }
  r.min_quality = min_quality(mesh);
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const double q = mesh.cell_quality(c);
    r.n_below_threshold += q < options.threshold;
    r.n_inverted += q <= 0;
  }
}

template <class M>
AdaptResult<M> run_base(const M& grid, const Fractions& fractions,
                        const IdVector<CellId, int>& material, const AdaptOptions& options) {
  AdaptResult<M> r;
  Timer clock;
  M mesh = grid;
  const auto boundary = boundary_constraints(mesh, options.boundary);
  const Targets targets = compute_targets(mesh, fractions, material, boundary, options.targets);
  r.n_interface_nodes = targets.n_interface_nodes;
  record(r, mesh, "targets", clock, options.progress, 0.1);

  r.dist_init = direct_move(mesh, targets).dist;
  record(r, mesh, "move", clock, options.progress, 0.3);

  GlobalPillowResult<M> p =
      global_pillow(mesh, material, fractions.n_materials(), options.boundary, options.pillow);
  record(r, p.mesh, "pillow", clock, options.progress, 0.6);

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
  record(r, p.mesh, "smooth", clock, options.progress, 1.0);

  r.mesh = std::move(p.mesh);
  r.material = std::move(p.material);
  finish(r, target, has, options);
  return r;
}

}  // namespace

template <class M>
AdaptResult<M> adapt(const M& grid, const Fractions& fractions,
                     const IdVector<CellId, int>& material, const AdaptOptions& options) {
  check_options(options);
  return run_base(grid, fractions, material, options);
}

template AdaptResult<QuadMesh> adapt<QuadMesh>(const QuadMesh&, const Fractions&,
                                               const IdVector<CellId, int>&, const AdaptOptions&);
template AdaptResult<HexMesh> adapt<HexMesh>(const HexMesh&, const Fractions&,
                                             const IdVector<CellId, int>&, const AdaptOptions&);

}  // namespace hexadapt
