// What every adaptation pipeline does between and after its steps: record the step in the
// result (minimum quality, cells, time) and fill the result's arrays and statistics at the
// end. Internal to the library: the pipelines (base, guaranteed) include it.
#pragma once

#include <string>
#include <string_view>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/core/timer.h"

namespace hexadapt::detail {

// Records a finished step, restarts the step clock and reports the phase that follows it
// (none when `next` is empty), `done` of the whole being behind.
template <class M>
void record_step(AdaptResult<M>& r, const M& mesh, const std::string& name, Timer& clock,
                 const Progress& progress, double done, std::string_view next) {
  r.steps.push_back({name, min_quality(mesh), mesh.n_cells(), clock.seconds()});
  clock.restart();
  if (progress && !next.empty()) progress(next, done);
}

// Sum over the nodes with targets of their distance to their surface.
template <class M>
double surface_distance_sum(const M& mesh, const Targets& targets,
                            const IdVector<NodeId, NodeConstraint>& surface) {
  double s = 0;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (targets.has[v]) s += surface_distance(mesh.point(v), targets.position[v], surface[v]);
  return s;
}

// The figures of the cells of r.mesh: least quality, shortest edge, the cells failing a
// criterion (counted, the worst ten kept) and the inverted ones.
template <class M>
void count_cells(AdaptResult<M>& r, const SizeCriterion& size, double threshold) {
  r.min_quality = min_quality(r.mesh);
  r.min_edge_ratio = min_edge_ratio(r.mesh, size);
  r.n_below_threshold = r.n_below_min_edge = r.n_inverted = 0;
  for (CellId c : id_range<CellId>(r.mesh.n_cells())) r.n_inverted += r.mesh.cell_quality(c) <= 0;
  std::vector<CellFailure> failures = failing_cells(r.mesh, threshold, size);
  for (const CellFailure& f : failures) {
    r.n_below_threshold += f.shape_failed(threshold);
    r.n_below_min_edge += f.size_failed();
  }
  r.failures = worst_failures(std::move(failures), 10);
}

// Fills the distances, quality and size figures of the output r.mesh; `size`: the size
// criterion on its cells; `surface`: each node's interface surface (nullptr: the target
// point itself).
template <class M>
void finish_result(AdaptResult<M>& r, const IdVector<NodeId, Vec3>& target,
                   const IdVector<NodeId, char>& has, const SizeCriterion& size,
                   const IdVector<NodeId, NodeConstraint>* surface, const AdaptOptions& options) {
  const M& mesh = r.mesh;
  r.target = target;
  r.has_target = has;
  if (surface) r.sliding = *surface;
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  r.distance.assign(nn, 0.0);
  r.surface_distance.assign(nn, 0.0);
  r.near_interface.assign(nn, 1);
  r.blocked.assign(nn, 0);
  r.dist_final = r.surface_dist_final = 0;
  r.n_reached = r.n_near_interface = 0;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (!has[v]) {
      r.target[v] = mesh.point(v);
      continue;
    }
    r.distance[v] = (mesh.point(v) - target[v]).norm();
    r.surface_distance[v] =
        surface ? surface_distance(mesh.point(v), target[v], (*surface)[v]) : r.distance[v];
    const double h = node_local_size(mesh, v, size);
    r.near_interface[v] = r.surface_distance[v] <= options.near_interface * h;
    if (r.surface_distance[v] > r.farthest_distance) {
      r.farthest = v;
      r.farthest_distance = r.surface_distance[v];
      r.farthest_local_size = h;
    }
    r.dist_final += r.distance[v];
    r.surface_dist_final += r.surface_distance[v];
    r.n_reached += r.distance[v] == 0;
    r.n_near_interface += r.near_interface[v];
  }
  count_cells(r, size, options.threshold);
  r.local_size = size.local_size;
}

}  // namespace hexadapt::detail
