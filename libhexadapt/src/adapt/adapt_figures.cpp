#include <algorithm>

#include "hexadapt/adapt/adapt_report.h"

namespace hexadapt {

namespace {

// The figures every count takes alike, whether a run's or a part's.
template <class M>
AdaptFigures common_figures(const AdaptResult<M>& r, index_t cells_in) {
  AdaptFigures f;
  f.cells_in = cells_in;
  f.cells = r.mesh.n_cells();
  f.below_threshold = r.n_below_threshold;
  f.inverted = r.n_inverted;
  f.below_min_edge = r.n_below_min_edge;
  f.dist_init = r.dist_init;
  f.surface_dist_init = r.surface_dist_init;
  f.min_quality = r.min_quality;
  f.min_edge_ratio = r.min_edge_ratio;
  f.input_min_quality = r.input_min_quality;
  f.loops = r.loops;
  return f;
}

}  // namespace

template <class M>
AdaptFigures adapt_figures(const AdaptResult<M>& r, index_t cells_in) {
  AdaptFigures f = common_figures(r, cells_in);
  f.nodes = r.mesh.n_nodes();
  f.interface_nodes = r.n_interface_nodes;
  f.reached = r.n_reached;
  f.near_interface = r.n_near_interface;
  f.blocked = r.n_blocked;
  f.frozen_blocked = r.n_frozen_blocked;
  f.dist_final = r.dist_final;
  f.surface_dist_final = r.surface_dist_final;
  if (r.farthest.valid())
    f.farthest = {true, r.farthest.value(), r.farthest_distance, r.farthest_local_size,
                  r.mesh.point(r.farthest)};
  return f;
}

template <class M>
AdaptFigures adapt_figures(const AdaptResult<M>& r, const IdVector<NodeId, char>& counted,
                           index_t cells_in, double seconds) {
  AdaptFigures f = common_figures(r, cells_in);
  f.seconds = seconds;
  const SizeCriterion sizes{0, r.local_size};
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    if (!counted[v]) continue;
    f.nodes += 1;
    if (!r.has_target[v]) continue;
    f.interface_nodes += 1;
    f.reached += r.distance[v] == 0;
    f.near_interface += r.near_interface[v] != 0;
    f.blocked += r.blocked[v] != 0;
    f.frozen_blocked += r.blocked[v] == static_cast<char>(BlockReason::frozen);
    f.dist_final += r.distance[v];
    f.surface_dist_final += r.surface_distance[v];
    if (r.blocked[v] != 0 && (!f.farthest.valid || r.surface_distance[v] > f.farthest.distance))
      f.farthest = {true, -1, r.surface_distance[v], node_local_size(r.mesh, v, sizes),
                    r.mesh.point(v)};
  }
  return f;
}

AdaptFigures summed(const std::vector<AdaptFigures>& parts) {
  AdaptFigures t;
  for (const AdaptFigures& f : parts) {
    for (auto [sum, part] :
         {std::pair{&t.cells_in, f.cells_in}, {&t.cells, f.cells}, {&t.nodes, f.nodes},
          {&t.interface_nodes, f.interface_nodes}, {&t.reached, f.reached},
          {&t.near_interface, f.near_interface}, {&t.blocked, f.blocked},
          {&t.frozen_blocked, f.frozen_blocked}, {&t.below_threshold, f.below_threshold},
          {&t.inverted, f.inverted}, {&t.below_min_edge, f.below_min_edge}})
      *sum += part;
    t.dist_init += f.dist_init;
    t.dist_final += f.dist_final;
    t.surface_dist_init += f.surface_dist_init;
    t.surface_dist_final += f.surface_dist_final;
    t.min_quality = std::min(t.min_quality, f.min_quality);
    t.min_edge_ratio = std::min(t.min_edge_ratio, f.min_edge_ratio);
    t.input_min_quality = std::min(t.input_min_quality, f.input_min_quality);
    t.loops = std::max(t.loops, f.loops);
    t.seconds = std::max(t.seconds, f.seconds);
    if (f.farthest.valid && (!t.farthest.valid || f.farthest.distance > t.farthest.distance))
      t.farthest = f.farthest;
  }
  return t;
}

template AdaptFigures adapt_figures(const AdaptResult<QuadMesh>&, index_t);
template AdaptFigures adapt_figures(const AdaptResult<HexMesh>&, index_t);
template AdaptFigures adapt_figures(const AdaptResult<QuadMesh>&, const IdVector<NodeId, char>&,
                                    index_t, double);
template AdaptFigures adapt_figures(const AdaptResult<HexMesh>&, const IdVector<NodeId, char>&,
                                    index_t, double);

}  // namespace hexadapt
