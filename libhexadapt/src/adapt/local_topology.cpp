#include "hexadapt/adapt/local_topology.h"

#include <algorithm>

namespace hexadapt {

// Each neighbour goes in its sorted place unless it is there already: a node has a few
// distinct neighbours, each seen from several cells.
template <class M>
std::vector<NodeId> edge_neighbours(const M& mesh, NodeId n) {
  const Span<CellId> cells = mesh.node_cells(n);
  std::vector<NodeId> out;
  out.reserve(static_cast<std::size_t>(M::dim) * cells.size());
  for (CellId c : cells) {
    const auto& nodes = mesh.cell_nodes(c);
    for (int k : corner_edge_neighbours<M>(corner_of(mesh, c, n))) {
      const NodeId o = nodes[static_cast<std::size_t>(k)];
      const auto at = std::lower_bound(out.begin(), out.end(), o);
      if (at == out.end() || *at != o) out.insert(at, o);
    }
  }
  return out;
}

template <class M>
Vec3 face_normal(const M& mesh, CellId c, int lf) {
  const auto f = mesh.face_nodes(c, lf);
  Vec3 n;
  if constexpr (M::dim == 2) {
    // Cells are counter-clockwise, so the outside of edge a->b is on its right.
    const Vec3 e = mesh.point(f[1]) - mesh.point(f[0]);
    n = Vec3(e.y(), -e.x(), 0.0);
  } else {
    n = (mesh.point(f[2]) - mesh.point(f[0])).cross(mesh.point(f[3]) - mesh.point(f[1]));
  }
  const double len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3(Vec3::Zero());
}

template <class M>
std::vector<std::vector<NodeId>> independent_node_sets(const M& mesh,
                                                       const std::vector<NodeId>& nodes) {
  IdVector<NodeId, int> colour(static_cast<std::size_t>(mesh.n_nodes()), -1);
  std::vector<std::vector<NodeId>> sets;
  std::vector<char> used;
  for (NodeId n : nodes) {
    used.assign(sets.size() + 1, 0);
    for (CellId c : mesh.node_cells(n))
      for (NodeId o : mesh.cell_nodes(c))
        if (colour[o] >= 0) used[static_cast<std::size_t>(colour[o])] = 1;
    const auto k = static_cast<std::size_t>(std::find(used.begin(), used.end(), 0) - used.begin());
    if (k == sets.size()) sets.emplace_back();
    sets[k].push_back(n);
    colour[n] = static_cast<int>(k);
  }
  return sets;
}

#define HEXADAPT_INSTANTIATE(M)                                                \
  template std::vector<NodeId> edge_neighbours<M>(const M&, NodeId);           \
  template Vec3 face_normal<M>(const M&, CellId, int);                         \
  template std::vector<std::vector<NodeId>> independent_node_sets<M>(const M&, \
                                                                     const std::vector<NodeId>&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
