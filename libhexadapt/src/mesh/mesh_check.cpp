#include "hexadapt/mesh/mesh_check.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/unit_frame.h"
#include "mesh_check_parts.h"

namespace hexadapt {

namespace mesh_check_detail {

template <class M>
std::vector<Vec3> all_points(const M& mesh) {
  std::vector<Vec3> points(static_cast<std::size_t>(mesh.n_nodes()));
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) points[n.idx()] = mesh.point(n);
  return points;
}

template <class M>
std::vector<FaceRef> boundary_faces(const M& mesh) {
  std::vector<FaceRef> out;
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int lf = 0; lf < M::faces_per_cell; ++lf)
      if (!mesh.neighbour(c, lf).valid()) out.push_back({c, lf});
  return out;
}

template std::vector<Vec3> all_points(const QuadMesh&);
template std::vector<Vec3> all_points(const HexMesh&);
template std::vector<FaceRef> boundary_faces(const QuadMesh&);
template std::vector<FaceRef> boundary_faces(const HexMesh&);

}  // namespace mesh_check_detail

namespace {

template <class M>
void find_unreferenced_nodes(const M& mesh, const std::vector<Vec3>& points,
                             const MeshCheckOptions& options, MeshCheckResult& result) {
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!mesh.node_cells(n).empty()) continue;
    if (++result.unreferenced_nodes <= options.max_listed)
      result.first_unreferenced.push_back({n, points[n.idx()], {}, -1, {}});
  }
}

template <class M>
void find_inverted_cells(const M& mesh, const MeshCheckOptions& options, MeshCheckResult& result) {
  std::vector<double> quality(static_cast<std::size_t>(mesh.n_cells()));
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    quality[static_cast<std::size_t>(i)] = mesh.cell_quality(CellId(i));
  });
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    if (!(quality[c.idx()] <= 0) && !std::isnan(quality[c.idx()])) continue;
    if (++result.inverted_cells <= options.max_listed)
      result.first_inverted.push_back({c, quality[c.idx()], cell_centroid(mesh, c)});
  }
}

template <class M>
MeshCheckResult check_as_given(const M& mesh, const MeshCheckOptions& options) {
  using namespace mesh_check_detail;
  MeshCheckResult result;
  const std::vector<Vec3> points = all_points(mesh);
  const std::vector<FaceRef> boundary = boundary_faces(mesh);
  result.boundary_faces = static_cast<index_t>(boundary.size());
  find_unreferenced_nodes(mesh, points, options, result);
  find_inverted_cells(mesh, options, result);
  find_duplicate_nodes(points, options, result);
  find_hanging_nodes(mesh, points, boundary, options, result);
  find_nonmanifold_nodes(mesh, points, options, result);
  return result;
}

// Positions and lengths of a result found in `frame` back in the mesh's units.
void to_world(MeshCheckResult& r, const UnitFrame& frame) {
  for (auto* list : {&r.first_hanging, &r.first_unreferenced, &r.first_duplicates,
                     &r.first_nonmanifold})
    for (NodeIssue& n : *list) n.position = frame.to_world(n.position);
  for (CellIssue& c : r.first_inverted) c.centroid = frame.to_world(c.centroid);
  r.duplicate_distance = frame.to_world(r.duplicate_distance);
}

}  // namespace

// A mesh of 1e-300 (or 1e300) is checked in its UnitFrame: there its Jacobians do not
// underflow (every cell would count as inverted) nor overflow.
template <class M>
MeshCheckResult check_mesh(const M& mesh, const MeshCheckOptions& options) {
  const UnitFrame frame = far_unit_frame(mesh);
  if (frame.is_identity()) return check_as_given(mesh, options);
  MeshCheckResult r = check_as_given(to_local(mesh, frame), options);
  to_world(r, frame);
  return r;
}

template MeshCheckResult check_mesh(const QuadMesh&, const MeshCheckOptions&);
template MeshCheckResult check_mesh(const HexMesh&, const MeshCheckOptions&);

}  // namespace hexadapt
