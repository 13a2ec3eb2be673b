// Non-manifold nodes: the star of a node (its cells) must be one piece glued through faces
// holding the node, and the boundary faces around it must form one fan: none (interior
// node) or, in 2D, exactly two boundary edges; in 3D, boundary quads whose sides at the node
// close into a single cycle around it (the link of the node is a disk). On a part, the rank
// owning a node tests it: a ghost layer around its cells holds the node's whole star.
#include <algorithm>
#include <map>
#include <numeric>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "mesh_check_parts.h"

namespace hexadapt::mesh_check_detail {

namespace {

template <class FaceNodes>
bool holds(const FaceNodes& nodes, NodeId n) {
  return std::find(nodes.begin(), nodes.end(), n) != nodes.end();
}

// Number of pieces of the star of n glued through faces holding n.
template <class M>
int star_components(const M& mesh, NodeId n) {
  const auto star = mesh.node_cells(n);
  std::vector<std::size_t> parent(star.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  int pieces = static_cast<int>(star.size());
  for (std::size_t i = 0; i < star.size(); ++i)
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(star[i], lf);
      if (!o.valid() || !holds(mesh.face_nodes(star[i], lf), n)) continue;
      const auto j =
          static_cast<std::size_t>(std::lower_bound(star.begin(), star.end(), o) - star.begin());
      const std::size_t a = root(i), b = root(j);
      if (a != b) {
        parent[a] = b;
        --pieces;
      }
    }
  return pieces;
}

// True when the boundary faces around n form one fan (or there are none).
template <class M>
bool boundary_is_one_fan(const M& mesh, NodeId n) {
  // The sides at n of each boundary face: 2D, the other end of the edge; 3D, the two face
  // neighbours of n, joined by the face (an edge of the node's link).
  std::vector<std::array<NodeId, 2>> link_edges;
  int boundary_edges = 0;
  for (CellId c : mesh.node_cells(n))
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      if (mesh.neighbour(c, lf).valid()) continue;
      const auto f = mesh.face_nodes(c, lf);
      const auto k = static_cast<std::size_t>(std::find(f.begin(), f.end(), n) - f.begin());
      if (k == f.size()) continue;
      ++boundary_edges;
      link_edges.push_back({f[(k + 1) % f.size()], f[(k + f.size() - 1) % f.size()]});
    }
  if constexpr (M::dim == 2) {
    return boundary_edges == 0 || boundary_edges == 2;
  } else {
    if (link_edges.empty()) return true;
    // One cycle: every link vertex has degree 2 and the edges are connected.
    std::map<NodeId, int> degree;
    for (const auto& e : link_edges) {
      ++degree[e[0]];
      ++degree[e[1]];
    }
    for (const auto& [v, d] : degree)
      if (d != 2) return false;
    std::vector<char> used(link_edges.size(), 0);
    std::vector<NodeId> todo = {link_edges[0][0]};
    std::size_t reached = 0;
    while (!todo.empty()) {
      const NodeId v = todo.back();
      todo.pop_back();
      for (std::size_t i = 0; i < link_edges.size(); ++i) {
        if (used[i] || (link_edges[i][0] != v && link_edges[i][1] != v)) continue;
        used[i] = 1;
        ++reached;
        todo.push_back(link_edges[i][0] == v ? link_edges[i][1] : link_edges[i][0]);
      }
    }
    return reached == link_edges.size();
  }
}

}  // namespace

template <class M>
void find_nonmanifold_nodes(const M& mesh, const PartIds& ids, const std::vector<Vec3>& points,
                            const MeshCheckOptions& options, MeshCheckResult& result) {
  std::vector<char> bad(static_cast<std::size_t>(mesh.n_nodes()), 0);
  parallel_for(mesh.n_nodes(), [&](std::int64_t i) {
    const NodeId n(i);
    if (!ids.owns_node(n.idx()) || mesh.node_cells(n).size() <= 1) return;
    bad[n.idx()] = star_components(mesh, n) > 1 || !boundary_is_one_fan(mesh, n);
  });
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!bad[n.idx()]) continue;
    if (++result.nonmanifold_nodes <= options.max_listed)
      result.first_nonmanifold.push_back({NodeId(ids.node(n.idx())), points[n.idx()], {}, -1, {}});
  }
}

template void find_nonmanifold_nodes(const QuadMesh&, const PartIds&, const std::vector<Vec3>&,
                                     const MeshCheckOptions&, MeshCheckResult&);
template void find_nonmanifold_nodes(const HexMesh&, const PartIds&, const std::vector<Vec3>&,
                                     const MeshCheckOptions&, MeshCheckResult&);

}  // namespace hexadapt::mesh_check_detail
