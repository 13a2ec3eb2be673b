// What every adaptation pipeline does between and after its steps: record the step in the
// result (minimum quality, cells, time) and fill the result's arrays and statistics at the
// end. Internal to the library: the pipelines (base, guaranteed) include it.
#pragma once

#include <limits>
#include <string>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/core/timer.h"

namespace hexadapt::detail {

// Records a finished step and restarts the step clock.
template <class M>
void record_step(AdaptResult<M>& r, const M& mesh, const std::string& name, Timer& clock,
                 const Progress& progress, double done) {
  r.steps.push_back({name, min_quality(mesh), mesh.n_cells(), clock.seconds()});
  clock.restart();
  if (progress) progress("adapt", done);
}

// Fills the distances, quality and size figures of the output r.mesh; `size`: the size
// criterion on its cells.
template <class M>
void finish_result(AdaptResult<M>& r, const IdVector<NodeId, Vec3>& target,
                   const IdVector<NodeId, char>& has, const SizeCriterion& size,
                   const AdaptOptions& options) {
  const M& mesh = r.mesh;
  r.target = target;
  r.has_target = has;
  r.distance.assign(static_cast<std::size_t>(mesh.n_nodes()), 0.0);
  r.blocked.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
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
  r.min_edge_ratio = std::numeric_limits<double>::infinity();
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const double q = mesh.cell_quality(c);
    r.n_below_threshold += q < options.threshold;
    r.n_inverted += q <= 0;
    r.min_edge_ratio = std::min(r.min_edge_ratio, cell_edge_lengths(mesh, c).min / size.local_size[c]);
  }
  if (mesh.n_cells() == 0) r.min_edge_ratio = 0;
  std::vector<CellFailure> failures = failing_cells(mesh, options.threshold, size);
  for (const CellFailure& f : failures) r.n_below_min_edge += f.size_failed();
  r.failures = worst_failures(std::move(failures), 10);
  r.local_size = size.local_size;
}

}  // namespace hexadapt::detail
