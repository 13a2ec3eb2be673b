// Duplicate nodes: distinct ids within a tolerance relative to the bounding-box diagonal,
// found through a uniform grid whose bucket is the tolerance itself (each query touches at
// most 2^3 buckets). On a part, a rank tests the nodes it owns against its own nodes and
// the other ranks' nodes within the tolerance of them (near_nodes.h).
#include <cstdint>
#include <limits>

#include "hexadapt/core/parallel.h"
#include "mesh_check_parts.h"
#include "near_nodes.h"
#include "point_grid.h"

namespace hexadapt::mesh_check_detail {

void find_duplicate_nodes(const dist::Communicator& comm, const PartIds& ids,
                          std::vector<Vec3>& points, const MeshCheckOptions& options,
                          MeshCheckResult& result) {
  const auto box = global_bounding_box(comm, points);
  const double tol = options.duplicate_tolerance * (box[1] - box[0]).norm();
  result.duplicate_distance = tol;
  std::vector<NodeId> owned;
  owned.reserve(points.size());
  const double inf = std::numeric_limits<double>::infinity();
  std::array<Vec3, 2> reach{Vec3::Constant(inf), Vec3::Constant(-inf)};  // empty
  for (std::size_t n = 0; n < points.size(); ++n)
    if (ids.owns_node(n)) {
      owned.push_back(NodeId(n));
      if (!points[n].allFinite()) continue;
      reach[0] = reach[0].cwiseMin(points[n] - Vec3::Constant(tol));
      reach[1] = reach[1].cwiseMax(points[n] + Vec3::Constant(tol));
    }
  const NearNodes near = nodes_near(comm, reach, points, std::move(owned), ids);
  const PointGrid grid(points, near.candidates, tol > 0 ? tol : 1.0);
  // Per owned node (the offered candidates), the lowest global id at the same place (-1: none).
  std::vector<std::int64_t> first(near.n_offered, -1);
  parallel_for(static_cast<std::int64_t>(near.n_offered), [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3& p = points[near.candidates[k].idx()];
    const std::int64_t id = ids.node(near.candidates[k].idx());
    const Vec3 d = Vec3::Constant(tol);
    std::int64_t& lowest = first[k];
    grid.for_each_in_box(p - d, p + d, [&](NodeId m) {
      const std::int64_t other = near.id(ids, m.idx());
      if (other < id && (lowest < 0 || other < lowest) && (points[m.idx()] - p).norm() <= tol)
        lowest = other;
    });
  });
  points.resize(near.n_local);
  for (std::size_t k = 0; k < near.n_offered; ++k) {
    if (first[k] < 0) continue;
    const std::size_t n = near.candidates[k].idx();
    if (++result.duplicate_nodes <= options.max_listed)
      result.first_duplicates.push_back({NodeId(ids.node(n)), points[n], {}, -1, NodeId(first[k])});
  }
}

}  // namespace hexadapt::mesh_check_detail
