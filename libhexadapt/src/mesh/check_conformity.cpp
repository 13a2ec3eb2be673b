// Hanging nodes (T-junctions): nodes lying on a boundary face of a cell without being one of
// its corners. Only nodes of boundary faces can hang (the small cells of a T-junction have
// boundary faces against the big one), so the uniform grid holds the boundary nodes only,
// with the mean boundary-face diameter as bucket size.
#include <algorithm>
#include <cmath>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "mesh_check_parts.h"
#include "point_grid.h"

namespace hexadapt::mesh_check_detail {

double distance_to_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

double distance_to_bilinear(const std::array<Vec3, 4>& q, const Vec3& p) {
  // x(u, v) = q0 + u e + v f + u v g; Gauss-Newton on |x - p|^2, clamped to the unit square.
  const Vec3 e = q[1] - q[0], f = q[3] - q[0], g = q[0] - q[1] + q[2] - q[3];
  double u = 0.5, v = 0.5;
  for (int it = 0; it < 30; ++it) {
    const Vec3 r = q[0] + u * e + v * f + u * v * g - p;
    const Vec3 xu = e + v * g, xv = f + u * g;
    const double a = xu.dot(xu), b = xu.dot(xv), c = xv.dot(xv);
    const double det = a * c - b * b;
    if (!(det > 0)) break;
    const double du = -(c * xu.dot(r) - b * xv.dot(r)) / det;
    const double dv = -(a * xv.dot(r) - b * xu.dot(r)) / det;
    const double nu = std::clamp(u + du, 0.0, 1.0), nv = std::clamp(v + dv, 0.0, 1.0);
    const bool still = std::abs(nu - u) < 1e-15 && std::abs(nv - v) < 1e-15;
    u = nu;
    v = nv;
    if (still) break;
  }
  double best = (q[0] + u * e + v * f + u * v * g - p).norm();
  // The clamped iteration may stall on a side: the sides are exact segments.
  for (std::size_t k = 0; k < 4; ++k)
    best = std::min(best, distance_to_segment(q[k], q[(k + 1) % 4], p));
  return best;
}

namespace {

template <std::size_t N>
double face_distance(const std::array<Vec3, N>& q, const Vec3& p) {
  if constexpr (N == 2) {
    return distance_to_segment(q[0], q[1], p);
  } else {
    return distance_to_bilinear(q, p);
  }
}

template <std::size_t N>
double diameter(const std::array<Vec3, N>& q) {
  double d = 0;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) d = std::max(d, (q[i] - q[j]).norm());
  return d;
}

struct Hit {
  NodeId node;
  std::size_t face;  // index into the boundary list
};

}  // namespace

template <class M>
void find_hanging_nodes(const M& mesh, const std::vector<Vec3>& points,
                        const std::vector<FaceRef>& boundary, const MeshCheckOptions& options,
                        MeshCheckResult& result) {
  constexpr auto N = static_cast<std::size_t>(M::nodes_per_face);
  if (boundary.empty()) return;
  std::vector<char> on_boundary(points.size(), 0);
  double mean_diameter = 0;
  for (const FaceRef& f : boundary) {
    std::array<Vec3, N> q;
    const auto nodes = mesh.face_nodes(f.cell, f.local_face);
    for (std::size_t k = 0; k < N; ++k) {
      on_boundary[nodes[k].idx()] = 1;
      q[k] = points[nodes[k].idx()];
    }
    mean_diameter += diameter(q) / double(boundary.size());
  }
  std::vector<NodeId> ids;
  for (std::size_t n = 0; n < points.size(); ++n)
    if (on_boundary[n]) ids.push_back(NodeId(n));
  const PointGrid grid(points, ids, mean_diameter);

  std::vector<std::vector<NodeId>> hits(boundary.size());
  parallel_for(static_cast<std::int64_t>(boundary.size()), [&](std::int64_t i) {
    const FaceRef& f = boundary[static_cast<std::size_t>(i)];
    const auto nodes = mesh.face_nodes(f.cell, f.local_face);
    std::array<Vec3, N> q;
    for (std::size_t k = 0; k < N; ++k) q[k] = points[nodes[k].idx()];
    const double tol = options.conformity_tolerance * diameter(q);
    Vec3 lo = q[0], hi = q[0];
    for (const Vec3& x : q) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    for (NodeId n : grid.in_box(lo - Vec3::Constant(tol), hi + Vec3::Constant(tol))) {
      if (std::find(nodes.begin(), nodes.end(), n) != nodes.end()) continue;
      const Vec3& p = points[n.idx()];
      // A node at a corner's place is a duplicate (reported as such), not a hanging node.
      bool at_corner = false;
      for (const Vec3& x : q) at_corner = at_corner || (x - p).norm() <= tol;
      if (!at_corner && face_distance(q, p) <= tol) hits[static_cast<std::size_t>(i)].push_back(n);
    }
  });

  std::vector<char> hanging(points.size(), 0);
  std::vector<FaceRef> face_of(points.size());
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    if (!hits[i].empty()) ++result.nonconformal_faces;
    for (NodeId n : hits[i])
      if (!hanging[n.idx()]) {
        hanging[n.idx()] = 1;
        face_of[n.idx()] = boundary[i];
      }
  }
  for (std::size_t n = 0; n < points.size(); ++n) {
    if (!hanging[n]) continue;
    if (++result.hanging_nodes <= options.max_listed)
      result.first_hanging.push_back(
          {NodeId(n), points[n], face_of[n].cell, face_of[n].local_face, {}});
  }
}

template void find_hanging_nodes(const QuadMesh&, const std::vector<Vec3>&,
                                 const std::vector<FaceRef>&, const MeshCheckOptions&,
                                 MeshCheckResult&);
template void find_hanging_nodes(const HexMesh&, const std::vector<Vec3>&,
                                 const std::vector<FaceRef>&, const MeshCheckOptions&,
                                 MeshCheckResult&);

}  // namespace hexadapt::mesh_check_detail
