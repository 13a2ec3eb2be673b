#include "hexadapt/mesh/mesh_check.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/core/parallel.h"
#include "hexadapt/dist/routing.h"
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
std::vector<FaceRef> boundary_faces(const M& mesh, const PartIds& ids) {
  std::vector<FaceRef> out;
  for (CellId c : id_range<CellId>(ids.owned_cells(mesh.n_cells())))
    for (int lf = 0; lf < M::faces_per_cell; ++lf)
      if (!mesh.neighbour(c, lf).valid()) out.push_back({c, lf});
  return out;
}

template std::vector<Vec3> all_points(const QuadMesh&);
template std::vector<Vec3> all_points(const HexMesh&);
template std::vector<FaceRef> boundary_faces(const QuadMesh&, const PartIds&);
template std::vector<FaceRef> boundary_faces(const HexMesh&, const PartIds&);

}  // namespace mesh_check_detail

namespace {

template <class M>
void find_unreferenced_nodes(const M& mesh, const PartIds& ids, const std::vector<Vec3>& points,
                             const MeshCheckOptions& options, MeshCheckResult& result) {
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!ids.owns_node(n.idx()) || !mesh.node_cells(n).empty()) continue;
    if (++result.unreferenced_nodes <= options.max_listed)
      result.first_unreferenced.push_back({NodeId(ids.node(n.idx())), points[n.idx()], {}, -1, {}});
  }
}

template <class M>
void find_inverted_cells(const M& mesh, const PartIds& ids, const MeshCheckOptions& options,
                         MeshCheckResult& result) {
  const index_t owned = ids.owned_cells(mesh.n_cells());
  std::vector<double> quality(static_cast<std::size_t>(owned));
  parallel_for(owned, [&](std::int64_t i) {
    quality[static_cast<std::size_t>(i)] = mesh.cell_quality(CellId(i));
  });
  for (CellId c : id_range<CellId>(owned)) {
    if (!(quality[c.idx()] <= 0) && !std::isnan(quality[c.idx()])) continue;
    if (++result.inverted_cells <= options.max_listed)
      result.first_inverted.push_back(
          {CellId(ids.cell(c.idx())), quality[c.idx()], cell_centroid(mesh, c)});
  }
}

// Every rank's counts added and lists merged by id: the result of the whole mesh.
void combine(const dist::Communicator& comm, int k, MeshCheckResult& r) {
  if (comm.size() == 1) return;
  for (index_t* count :
       {&r.hanging_nodes, &r.nonconformal_faces, &r.unreferenced_nodes, &r.duplicate_nodes,
        &r.inverted_cells, &r.nonmanifold_nodes, &r.boundary_faces})
    *count = static_cast<index_t>(dist::sum_in_rank_order(comm, std::int64_t{*count}));
  for (auto* list :
       {&r.first_hanging, &r.first_unreferenced, &r.first_duplicates, &r.first_nonmanifold})
    *list = first_of_ranks(comm, std::move(*list), k);
  r.first_inverted = first_of_ranks(comm, std::move(r.first_inverted), k);
}

template <class M>
MeshCheckResult check_as_given(const dist::Communicator& comm, const M& mesh, const PartIds& ids,
                               const MeshCheckOptions& options) {
  using namespace mesh_check_detail;
  MeshCheckResult result;
  std::vector<Vec3> points = all_points(mesh);
  const std::vector<FaceRef> boundary = boundary_faces(mesh, ids);
  result.boundary_faces = static_cast<index_t>(boundary.size());
  find_unreferenced_nodes(mesh, ids, points, options, result);
  find_inverted_cells(mesh, ids, options, result);
  find_duplicate_nodes(comm, ids, points, options, result);
  find_hanging_nodes(comm, mesh, ids, points, boundary, options, result);
  find_nonmanifold_nodes(mesh, ids, points, options, result);
  combine(comm, options.max_listed, result);
  return result;
}

// Positions and lengths of a result found in `frame` back in the mesh's units.
void to_world(MeshCheckResult& r, const UnitFrame& frame) {
  for (auto* list :
       {&r.first_hanging, &r.first_unreferenced, &r.first_duplicates, &r.first_nonmanifold})
    for (NodeIssue& n : *list) n.position = frame.to_world(n.position);
  for (CellIssue& c : r.first_inverted) c.centroid = frame.to_world(c.centroid);
  r.duplicate_distance = frame.to_world(r.duplicate_distance);
}

}  // namespace

std::vector<NodeIssue> first_of_ranks(const dist::Communicator& comm, std::vector<NodeIssue> mine,
                                      int k) {
  return dist::first_of_ranks(
      comm, std::move(mine), static_cast<std::size_t>(std::max(k, 0)),
      [](dist::Buffer& b, const NodeIssue& n) {
        b.put(n.node);
        b.put_point(n.position);
        b.put(n.cell);
        b.put(n.local_face);
        b.put(n.other);
      },
      [](dist::Buffer& b) {
        NodeIssue n;
        n.node = b.get<NodeId>();
        n.position = b.get_point();
        n.cell = b.get<CellId>();
        n.local_face = b.get<int>();
        n.other = b.get<NodeId>();
        return n;
      },
      [](const NodeIssue& a, const NodeIssue& b) { return a.node < b.node; });
}

std::vector<CellIssue> first_of_ranks(const dist::Communicator& comm, std::vector<CellIssue> mine,
                                      int k) {
  return dist::first_of_ranks(
      comm, std::move(mine), static_cast<std::size_t>(std::max(k, 0)),
      [](dist::Buffer& b, const CellIssue& c) {
        b.put(c.cell);
        b.put(c.quality);
        b.put_point(c.centroid);
      },
      [](dist::Buffer& b) {
        CellIssue c;
        c.cell = b.get<CellId>();
        c.quality = b.get<double>();
        c.centroid = b.get_point();
        return c;
      },
      [](const CellIssue& a, const CellIssue& b) { return a.cell < b.cell; });
}

// A mesh of 1e-300 (or 1e300) is checked in its UnitFrame: there its Jacobians do not
// underflow (every cell would count as inverted) nor overflow.
template <class M>
MeshCheckResult check_mesh(const dist::Communicator& comm, const M& part, const PartIds& ids,
                           const MeshCheckOptions& options) {
  const UnitFrame frame = far_unit_frame(part, comm);
  if (frame.is_identity()) return check_as_given(comm, part, ids, options);
  MeshCheckResult r = check_as_given(comm, to_local(part, frame), ids, options);
  to_world(r, frame);
  return r;
}

template <class M>
MeshCheckResult check_mesh(const M& mesh, const MeshCheckOptions& options) {
  return check_mesh(dist::serial(), mesh, PartIds(), options);
}

template MeshCheckResult check_mesh(const QuadMesh&, const MeshCheckOptions&);
template MeshCheckResult check_mesh(const HexMesh&, const MeshCheckOptions&);
template MeshCheckResult check_mesh(const dist::Communicator&, const QuadMesh&, const PartIds&,
                                    const MeshCheckOptions&);
template MeshCheckResult check_mesh(const dist::Communicator&, const HexMesh&, const PartIds&,
                                    const MeshCheckOptions&);

}  // namespace hexadapt
