#include "near_nodes.h"

#include <limits>

#include "hexadapt/dist/routing.h"
#include "point_grid.h"

namespace hexadapt {

namespace {

bool inside(const std::array<Vec3, 2>& box, const Vec3& p) {
  return (p.array() >= box[0].array()).all() && (p.array() <= box[1].array()).all();
}

struct Offered {
  std::int64_t id;
  double x, y, z;
};

}  // namespace

NearNodes nodes_near(const dist::Communicator& comm, const std::array<Vec3, 2>& box,
                     std::vector<Vec3>& points, std::vector<NodeId> offered, const PartIds& ids) {
  NearNodes near;
  near.n_local = points.size();
  near.n_offered = offered.size();
  near.candidates = std::move(offered);
  if (comm.size() == 1) return near;
  const std::vector<double> boxes = dist::all_gather_values(
      comm,
      std::vector<double>{box[0].x(), box[0].y(), box[0].z(), box[1].x(), box[1].y(), box[1].z()});
  const auto n_ranks = static_cast<std::size_t>(comm.size());
  std::vector<std::vector<Offered>> to(n_ranks);
  for (std::size_t r = 0; r < n_ranks; ++r) {
    if (static_cast<int>(r) == comm.rank()) continue;
    const double* b = &boxes[6 * r];
    const std::array<Vec3, 2> other{Vec3(b[0], b[1], b[2]), Vec3(b[3], b[4], b[5])};
    for (std::size_t k = 0; k < near.n_offered; ++k) {
      const Vec3& p = points[near.candidates[k].idx()];
      if (inside(other, p))
        to[r].push_back({ids.node(near.candidates[k].idx()), p.x(), p.y(), p.z()});
    }
  }
  const std::vector<std::vector<Offered>> from = dist::all_to_all(comm, std::move(to));
  for (std::size_t r = 0; r < n_ranks; ++r) {
    if (static_cast<int>(r) == comm.rank()) continue;
    for (const Offered& o : from[r]) {
      near.candidates.push_back(NodeId(points.size()));
      points.emplace_back(o.x, o.y, o.z);
      near.received_ids.push_back(o.id);
      near.received_owner.push_back(static_cast<int>(r));
    }
  }
  return near;
}

std::array<Vec3, 2> global_bounding_box(const dist::Communicator& comm,
                                        const std::vector<Vec3>& points) {
  if (comm.size() == 1) return bounding_box(points);
  // Every rank's finite points' box (empty: lo > hi); the box of their corners.
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 lo = Vec3::Constant(inf), hi = Vec3::Constant(-inf);
  for (const Vec3& p : points)
    if (p.allFinite()) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const std::vector<double> all = dist::all_gather_values(
      comm, std::vector<double>{lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()});
  std::vector<Vec3> corners;
  for (std::size_t i = 0; i + 6 <= all.size(); i += 6)
    if (all[i] <= all[i + 3]) {
      corners.emplace_back(all[i], all[i + 1], all[i + 2]);
      corners.emplace_back(all[i + 3], all[i + 4], all[i + 5]);
    }
  return bounding_box(corners);
}

std::int64_t local_node(const PartIds& ids, std::size_t n_nodes, std::int64_t g) {
  std::size_t lo = 0, hi = n_nodes;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (ids.node(mid) < g)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < n_nodes && ids.node(lo) == g ? static_cast<std::int64_t>(lo) : -1;
}

}  // namespace hexadapt
