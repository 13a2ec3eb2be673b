#include "own_part.h"

#include <vector>

namespace hexadapt::cli {

template <class M>
OwnPart<M> own_part(const AdaptResult<M>& r, std::array<index_t, 2> cells,
                    std::array<index_t, 2> nodes) {
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
  OwnPart<M> part{r, from, {}};
  AdaptResult<M>& out = part.result;
  std::vector<Vec3> points;
  for (NodeId v : from) points.push_back(r.mesh.point(v));
  std::vector<typename M::CellNodes> cell_nodes;
  out.material.raw().clear();
  out.local_size.raw().clear();
  out.cell_origin.raw().clear();
  for (CellId c : kept) {
    typename M::CellNodes n = r.mesh.cell_nodes(c);
    for (NodeId& v : n) v = NodeId(to[v.idx()]);
    cell_nodes.push_back(n);
    out.material.push_back(r.material[c]);
    out.local_size.push_back(r.local_size[c]);
    out.cell_origin.push_back(r.cell_origin[c]);
  }
  out.mesh = M(std::move(points), std::move(cell_nodes));
  const auto pick = [&](auto& values, const auto& all) {  // a result stopped on its input
    values.raw().clear();                                 // has no sliding constraints
    if (all.size() == 0) return;
    for (NodeId v : from) values.push_back(all[v]);
  };
  pick(out.target, r.target);
  pick(out.has_target, r.has_target);
  pick(out.distance, r.distance);
  pick(out.surface_distance, r.surface_distance);
  pick(out.near_interface, r.near_interface);
  pick(out.sliding, r.sliding);
  pick(out.blocked, r.blocked);
  pick(out.node_origin, r.node_origin);
  for (CellId c : kept)
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId across = r.mesh.neighbour(c, lf);
      if (!across.valid() || own(across)) continue;
      typename M::FaceNodes face = r.mesh.face_nodes(c, lf);
      for (NodeId& v : face) v = NodeId(to[v.idx()]);
      part.cut_faces.push_back(face);
    }
  return part;
}

template OwnPart<QuadMesh> own_part<QuadMesh>(const AdaptResult<QuadMesh>&, std::array<index_t, 2>,
                                              std::array<index_t, 2>);
template OwnPart<HexMesh> own_part<HexMesh>(const AdaptResult<HexMesh>&, std::array<index_t, 2>,
                                            std::array<index_t, 2>);

}  // namespace hexadapt::cli
