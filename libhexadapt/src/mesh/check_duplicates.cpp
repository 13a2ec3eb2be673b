// Duplicate nodes: distinct ids within a tolerance relative to the bounding-box diagonal,
// found through a uniform grid whose bucket is the tolerance itself (each query touches at
// most 2^3 buckets).
#include <cstdint>

#include "hexadapt/core/parallel.h"
#include "mesh_check_parts.h"
#include "point_grid.h"

namespace hexadapt::mesh_check_detail {

void find_duplicate_nodes(const std::vector<Vec3>& points, const MeshCheckOptions& options,
                          MeshCheckResult& result) {
  const auto box = bounding_box(points);
  const double tol = options.duplicate_tolerance * (box[1] - box[0]).norm();
  result.duplicate_distance = tol;
  std::vector<NodeId> ids(points.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = NodeId(i);
  const PointGrid grid(points, ids, tol > 0 ? tol : 1.0);
  std::vector<NodeId> first(points.size());  // the lowest-id node at the same place
  parallel_for(static_cast<std::int64_t>(points.size()), [&](std::int64_t i) {
    const Vec3& p = points[static_cast<std::size_t>(i)];
    const Vec3 d = Vec3::Constant(tol);
    NodeId lowest;
    grid.for_each_in_box(p - d, p + d, [&](NodeId m) {
      if (m.value() < i && (!lowest.valid() || m < lowest) && (points[m.idx()] - p).norm() <= tol)
        lowest = m;
    });
    first[static_cast<std::size_t>(i)] = lowest;
  });
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!first[i].valid()) continue;
    if (++result.duplicate_nodes <= options.max_listed)
      result.first_duplicates.push_back({NodeId(i), points[i], {}, -1, first[i]});
  }
}

}  // namespace hexadapt::mesh_check_detail
