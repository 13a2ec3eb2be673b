#include "hexadapt/assign/local_ball.h"

#include <algorithm>
#include <string>
#include <utility>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

template <class M>
std::vector<CellId> cells_in_geometric_order(const M& mesh, NodeId n) {
  std::vector<std::pair<Vec3, CellId>> keyed;
  for (CellId c : mesh.node_cells(n)) keyed.emplace_back(cell_centroid(mesh, c), c);
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    for (int d = 0; d < 3; ++d)
      if (a.first[d] != b.first[d]) return a.first[d] < b.first[d];
    return a.second < b.second;
  });
  std::vector<CellId> cells;
  for (const auto& kc : keyed) cells.push_back(kc.second);
  return cells;
}

int local_of(const std::vector<NodeId>& sorted, NodeId v) {
  return static_cast<int>(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
}

}  // namespace

template <class M>
LocalBall<M>::LocalBall(const M& mesh, NodeId n) : node_(n) {
  cells_ = cells_in_geometric_order(mesh, n);
  if (n_cells() > max_cells)
    throw MeshError("node " + std::to_string(n.value()) + " has " + std::to_string(n_cells()) +
                    " cells; the assignment supports at most " + std::to_string(max_cells));
  std::vector<NodeId> nodes;
  for (CellId c : cells_)
    for (NodeId v : mesh.cell_nodes(c)) nodes.push_back(v);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  n_nodes_ = static_cast<int>(nodes.size());

  if (n_nodes_ > max_local) throw InternalError("local ball ids exceed their bound");
  faces_.resize(cells_.size());
  // Edge ids in order of first sight, through a small node x node table.
  std::vector<std::int16_t> edge_id;
  if constexpr (M::dim == 3)
    edge_id.assign(static_cast<std::size_t>(n_nodes_) * static_cast<std::size_t>(n_nodes_), -1);
  for (std::size_t i = 0; i < cells_.size(); ++i)
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      Face& f = faces_[i][static_cast<std::size_t>(lf)];
      const CellId nb = mesh.neighbour(cells_[i], lf);
      const auto it = std::find(cells_.begin(), cells_.end(), nb);
      f.neighbour = nb.valid() && it != cells_.end() ? static_cast<int>(it - cells_.begin()) : -1;
      const auto fn = mesh.face_nodes(cells_[i], lf);
      for (int k = 0; k < M::nodes_per_face; ++k)
        f.nodes[static_cast<std::size_t>(k)] =
            static_cast<std::uint16_t>(local_of(nodes, fn[static_cast<std::size_t>(k)]));
      if constexpr (M::dim == 3)
        for (int k = 0; k < M::nodes_per_face; ++k) {
          const int a = f.nodes[static_cast<std::size_t>(k)];
          const int b = f.nodes[static_cast<std::size_t>((k + 1) % M::nodes_per_face)];
          auto& id = edge_id[static_cast<std::size_t>(std::min(a, b) * n_nodes_ + std::max(a, b))];
          if (id < 0) id = static_cast<std::int16_t>(n_edges_++);
          f.edges[static_cast<std::size_t>(k)] = static_cast<std::uint16_t>(id);
        }
    }
  if (n_edges_ > max_local) throw InternalError("local ball ids exceed their bound");
  if constexpr (M::dim == 3) build_fans(local_of(nodes, n));
}

template <class M>
void LocalBall<M>::build_fans(int centre) {
  // Edges through the centre node, by local edge id.
  std::vector<int> through(static_cast<std::size_t>(n_edges_), -1);
  for (const auto& cell_faces : faces_)
    for (const Face& f : cell_faces)
      for (int k = 0; k < M::nodes_per_face; ++k) {
        const int a = f.nodes[static_cast<std::size_t>(k)];
        const int b = f.nodes[static_cast<std::size_t>((k + 1) % M::nodes_per_face)];
        const auto e = f.edges[static_cast<std::size_t>(k)];
        if ((a == centre || b == centre) && through[e] < 0) {
          through[e] = static_cast<int>(fans_.size());
          fans_.push_back(Fan{0, std::vector<std::uint64_t>(cells_.size(), 0)});
        }
      }
  for (std::size_t i = 0; i < cells_.size(); ++i)
    for (const Face& f : faces_[i])
      for (auto e : f.edges) {
        if (through[e] < 0) continue;
        Fan& fan = fans_[static_cast<std::size_t>(through[e])];
        fan.cells |= std::uint64_t{1} << i;
        if (f.neighbour >= 0) fan.next_to[i] |= std::uint64_t{1} << f.neighbour;
      }
}

template class LocalBall<QuadMesh>;
template class LocalBall<HexMesh>;

}  // namespace hexadapt::assign
