// Duplicate nodes: distinct ids within a tolerance relative to the bounding-box diagonal,
// found through a uniform grid whose bucket is the tolerance itself (each query touches at
// most 2^3 buckets). On a part, a rank tests the nodes it owns against its own nodes and
// the other ranks' nodes within the tolerance of them (near_nodes.h).
#include <cstdint>

#include "hexadapt/core/parallel.h"
#include "mesh_check_parts.h"
#include "near_nodes.h"
#include "point_grid.h"

namespace hexadapt::mesh_check_detail {

void find_duplicate_nodes(const dist::Communicator& comm, const PartIds& ids,
                          const std::vector<Vec3>& points, const MeshCheckOptions& options,
                          MeshCheckResult& result) {
  const auto box = global_bounding_box(comm, points);
  const double tol = options.duplicate_tolerance * (box[1] - box[0]).norm();
  result.duplicate_distance = tol;
  std::vector<std::size_t> owned;
  std::vector<Vec3> owned_points;
  for (std::size_t n = 0; n < points.size(); ++n)
    if (ids.owns_node(n)) {
      owned.push_back(n);
      owned_points.push_back(points[n]);
    }
  auto reach = bounding_box(owned_points);
  reach[0] -= Vec3::Constant(tol);
  reach[1] += Vec3::Constant(tol);
  if (owned.empty()) reach = {Vec3::Constant(1), Vec3::Zero()};  // empty: receives nothing
  const NearNodes near = nodes_near(comm, reach, points, owned, ids);
  std::vector<NodeId> all(near.points.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = NodeId(i);
  const PointGrid grid(near.points, all, tol > 0 ? tol : 1.0);
  // Per owned node, the lowest global id at the same place (-1: none).
  std::vector<std::int64_t> first(owned.size(), -1);
  parallel_for(static_cast<std::int64_t>(owned.size()), [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3& p = near.points[k];
    const std::int64_t id = near.ids[k];
    const Vec3 d = Vec3::Constant(tol);
    std::int64_t& lowest = first[k];
    grid.for_each_in_box(p - d, p + d, [&](NodeId m) {
      const std::int64_t other = near.ids[m.idx()];
      if (other < id && (lowest < 0 || other < lowest) && (near.points[m.idx()] - p).norm() <= tol)
        lowest = other;
    });
  });
  for (std::size_t k = 0; k < owned.size(); ++k) {
    if (first[k] < 0) continue;
    if (++result.duplicate_nodes <= options.max_listed)
      result.first_duplicates.push_back(
          {NodeId(near.ids[k]), points[owned[k]], {}, -1, NodeId(first[k])});
  }
}

}  // namespace hexadapt::mesh_check_detail
