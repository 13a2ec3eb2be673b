// Hanging nodes (T-junctions): nodes lying on a boundary face of a cell without being one of
// its corners. Only nodes of boundary faces can hang (the small cells of a T-junction have
// boundary faces against the big one), so the uniform grid holds the boundary nodes only,
// with the mean boundary-face diameter as bucket size.
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "hexadapt/core/parallel.h"
#include "hexadapt/dist/routing.h"
#include "hexadapt/mesh/cell_complex.h"
#include "mesh_check_parts.h"
#include "near_nodes.h"
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

// The boundary nodes of a part: nodes of a face with no cell on its other side. Exact for
// the owned nodes (their whole star, and every cell across a face holding them, is local).
template <class M>
std::vector<char> boundary_nodes(const M& mesh) {
  std::vector<char> on_boundary(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int lf = 0; lf < M::faces_per_cell; ++lf)
      if (!mesh.neighbour(c, lf).valid())
        for (NodeId n : mesh.face_nodes(c, lf)) on_boundary[n.idx()] = 1;
  return on_boundary;
}

// A node found on a face: sent to the node's owner, who counts it once.
struct Hit {
  std::int64_t node, cell;
  std::int32_t local_face, pad = 0;
};

// Counts and lists the owned nodes that some face holds, each with the lowest (cell, local
// face) holding it, as the faces appear in the boundary list of the whole mesh.
void count_hanging(const dist::Communicator& comm, const PartIds& ids,
                   const std::vector<Vec3>& points, std::vector<std::vector<Hit>> to_owner,
                   const MeshCheckOptions& options, MeshCheckResult& result) {
  std::vector<Hit> hits = dist::joined(dist::all_to_all(comm, std::move(to_owner)));
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return std::tie(a.node, a.cell, a.local_face) < std::tie(b.node, b.cell, b.local_face);
  });
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (i > 0 && hits[i].node == hits[i - 1].node) continue;
    const Hit& h = hits[i];
    if (++result.hanging_nodes > options.max_listed) continue;
    const auto n = static_cast<std::size_t>(local_node(ids, points.size(), h.node));
    result.first_hanging.push_back(
        {NodeId(h.node), points[n], CellId(h.cell), static_cast<int>(h.local_face), {}});
  }
}

}  // namespace

template <class M>
void find_hanging_nodes(const dist::Communicator& comm, const M& mesh, const PartIds& ids,
                        std::vector<Vec3>& points, const std::vector<FaceRef>& boundary,
                        const MeshCheckOptions& options, MeshCheckResult& result) {
  constexpr auto N = static_cast<std::size_t>(M::nodes_per_face);
  const auto corners = [&](const FaceRef& f) {
    const auto nodes = mesh.face_nodes(f.cell, f.local_face);
    std::array<Vec3, N> q;
    for (std::size_t k = 0; k < N; ++k) q[k] = points[nodes[k].idx()];
    return q;
  };
  // The region of the faces, their tolerances included.
  const double inf = std::numeric_limits<double>::infinity();
  std::array<Vec3, 2> reach{Vec3::Constant(inf), Vec3::Constant(-inf)};  // empty
  double mean_diameter = 0;
  for (const FaceRef& f : boundary) {
    const std::array<Vec3, N> q = corners(f);
    const double d = diameter(q);
    mean_diameter += d / double(boundary.size());
    for (const Vec3& x : q) {
      reach[0] = reach[0].cwiseMin(x - Vec3::Constant(options.conformity_tolerance * d));
      reach[1] = reach[1].cwiseMax(x + Vec3::Constant(options.conformity_tolerance * d));
    }
  }
  const std::vector<char> on_boundary = boundary_nodes(mesh);
  std::vector<NodeId> offered;
  for (std::size_t n = 0; n < points.size(); ++n)
    if (on_boundary[n] && ids.owns_node(n)) offered.push_back(NodeId(n));
  const NearNodes near = nodes_near(comm, reach, points, std::move(offered), ids);
  const PointGrid grid(points, near.candidates, mean_diameter);

  std::vector<std::vector<NodeId>> hits(boundary.size());
  parallel_for(static_cast<std::int64_t>(boundary.size()), [&](std::int64_t i) {
    const auto f = static_cast<std::size_t>(i);
    const auto nodes = mesh.face_nodes(boundary[f].cell, boundary[f].local_face);
    const std::array<Vec3, N> q = corners(boundary[f]);
    const double tol = options.conformity_tolerance * diameter(q);
    Vec3 lo = q[0], hi = q[0];
    for (const Vec3& x : q) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    for (NodeId m : grid.in_box(lo - Vec3::Constant(tol), hi + Vec3::Constant(tol))) {
      const std::int64_t id = near.id(ids, m.idx());
      if (std::any_of(nodes.begin(), nodes.end(),
                      [&](NodeId c) { return ids.node(c.idx()) == id; }))
        continue;
      const Vec3& p = points[m.idx()];
      // A node at a corner's place is a duplicate (reported as such), not a hanging node.
      bool at_corner = false;
      for (const Vec3& x : q) at_corner = at_corner || (x - p).norm() <= tol;
      if (!at_corner && face_distance(q, p) <= tol) hits[f].push_back(m);
    }
  });

  std::vector<std::vector<Hit>> to_owner(static_cast<std::size_t>(comm.size()));
  for (std::size_t f = 0; f < boundary.size(); ++f) {
    if (!hits[f].empty()) ++result.nonconformal_faces;
    for (NodeId m : hits[f])
      to_owner[static_cast<std::size_t>(near.owner(comm.rank(), m.idx()))].push_back(
          {near.id(ids, m.idx()), ids.cell(boundary[f].cell.idx()), boundary[f].local_face});
  }
  points.resize(near.n_local);
  count_hanging(comm, ids, points, std::move(to_owner), options, result);
}

template void find_hanging_nodes(const dist::Communicator&, const QuadMesh&, const PartIds&,
                                 std::vector<Vec3>&, const std::vector<FaceRef>&,
                                 const MeshCheckOptions&, MeshCheckResult&);
template void find_hanging_nodes(const dist::Communicator&, const HexMesh&, const PartIds&,
                                 std::vector<Vec3>&, const std::vector<FaceRef>&,
                                 const MeshCheckOptions&, MeshCheckResult&);

}  // namespace hexadapt::mesh_check_detail
