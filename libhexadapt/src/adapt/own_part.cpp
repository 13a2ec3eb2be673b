#include "own_part.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace hexadapt {

namespace {

// The values of `all` at `from`, in that order; none when `all` has none (a result stopped on
// its input has no sliding constraints).
template <class Id, class T>
IdVector<Id, T> picked(const IdVector<Id, T>& all, const std::vector<Id>& from) {
  IdVector<Id, T> out;
  if (all.size() == 0) return out;
  for (Id v : from) out.push_back(all[v]);
  return out;
}

}  // namespace

template <class M>
OwnPart<M> own_part(AdaptResult<M> r, std::array<index_t, 2> cells, std::array<index_t, 2> nodes) {
  const auto own = [&](CellId c) {
    return r.cell_origin[c].value() >= cells[0] && r.cell_origin[c].value() < cells[1];
  };
  std::vector<CellId> kept;
  for (CellId c : id_range<CellId>(r.mesh.n_cells()))
    if (own(c)) kept.push_back(c);
  std::vector<index_t> to(static_cast<std::size_t>(r.mesh.n_nodes()), -1);
  std::vector<NodeId> from;
  for (index_t v = nodes[0]; v < nodes[1]; ++v) {
    to[static_cast<std::size_t>(v)] = static_cast<index_t>(from.size());
    from.emplace_back(v);
  }
  std::vector<char> used(static_cast<std::size_t>(r.mesh.n_nodes()), 0);
  for (CellId c : kept)
    for (NodeId v : r.mesh.cell_nodes(c)) used[v.idx()] = 1;
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes()))
    if (used[v.idx()] && to[v.idx()] < 0) {
      to[v.idx()] = static_cast<index_t>(from.size());
      from.push_back(v);
    }
  OwnPart<M> part;
  for (NodeId v : from) {
    std::vector<CellId>& around = part.around.emplace_back();
    if (v.idx() >= r.sliding.size() || !r.sliding[v].frozen()) continue;
    for (CellId c : r.mesh.node_cells(v)) around.push_back(r.cell_origin[c]);
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
  std::vector<Vec3> points;
  for (NodeId v : from) points.push_back(r.mesh.point(v));
  std::vector<typename M::CellNodes> cell_nodes;
  for (CellId c : kept) {
    typename M::CellNodes n = r.mesh.cell_nodes(c);
    for (NodeId& v : n) v = NodeId(to[v.idx()]);
    cell_nodes.push_back(n);
  }
  for (CellId c : kept)
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId across = r.mesh.neighbour(c, lf);
      if (!across.valid() || own(across)) continue;
      typename M::FaceNodes face = r.mesh.face_nodes(c, lf);
      for (NodeId& v : face) v = NodeId(to[v.idx()]);
      part.cut_faces.push_back(face);
      part.cut_across.push_back(r.cell_origin[across]);
    }
  AdaptResult<M>& out = part.result;
  out = std::move(r);
  out.mesh = M(std::move(points), std::move(cell_nodes));
  out.material = picked(out.material, kept);
  out.local_size = picked(out.local_size, kept);
  out.cell_origin = picked(out.cell_origin, kept);
  out.target = picked(out.target, from);
  out.has_target = picked(out.has_target, from);
  out.distance = picked(out.distance, from);
  out.surface_distance = picked(out.surface_distance, from);
  out.near_interface = picked(out.near_interface, from);
  out.sliding = picked(out.sliding, from);
  out.blocked = picked(out.blocked, from);
  out.node_origin = picked(out.node_origin, from);
  return part;
}

template OwnPart<QuadMesh> own_part<QuadMesh>(AdaptResult<QuadMesh>, std::array<index_t, 2>,
                                              std::array<index_t, 2>);
template OwnPart<HexMesh> own_part<HexMesh>(AdaptResult<HexMesh>, std::array<index_t, 2>,
                                            std::array<index_t, 2>);

}  // namespace hexadapt
