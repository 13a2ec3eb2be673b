#include "cavity_patch.h"

#include <algorithm>

#include "hexadapt/core/error.h"

namespace hexadapt::detail {

namespace {

template <class T>
void insert_sorted(std::vector<T>& v, T x) {
  v.insert(std::lower_bound(v.begin(), v.end(), x), x);
}

template <class T>
void erase_sorted(std::vector<T>& v, T x) {
  const auto it = std::lower_bound(v.begin(), v.end(), x);
  if (it != v.end() && *it == x) v.erase(it);
}

template <class A>
bool holds(const A& nodes, NodeId n) {
  return std::find(nodes.begin(), nodes.end(), n) != nodes.end();
}

}  // namespace

template <class M>
EditableMesh<M>::EditableMesh(const M& mesh)
    : node_cells_(static_cast<std::size_t>(mesh.n_nodes())) {
  points_.reserve(static_cast<std::size_t>(mesh.n_nodes()));
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    points_.push_back(mesh.point(v));
    const auto around = mesh.node_cells(v);
    node_cells_[v.idx()].assign(around.begin(), around.end());
  }
  cells_.reserve(static_cast<std::size_t>(mesh.n_cells()));
  for (CellId c : id_range<CellId>(mesh.n_cells())) cells_.push_back(mesh.cell_nodes(c));
}

template <class M>
CavityPatch<M> EditableMesh<M>::patch(const std::vector<CellId>& set, bool whole) const {
  CavityPatch<M> out;
  if (whole) {
    for (CellId c : id_range<CellId>(n_cells())) out.cells.push_back(c);
  } else {
    for (CellId c : set)
      for (NodeId n : cells_[c.idx()])
        for (CellId o : node_cells_[n.idx()]) out.cells.push_back(o);
    std::sort(out.cells.begin(), out.cells.end());
    out.cells.erase(std::unique(out.cells.begin(), out.cells.end()), out.cells.end());
  }
  for (CellId c : out.cells)
    for (NodeId n : cells_[c.idx()]) out.nodes.push_back(n);
  std::sort(out.nodes.begin(), out.nodes.end());
  out.nodes.erase(std::unique(out.nodes.begin(), out.nodes.end()), out.nodes.end());

  std::vector<Vec3> points;
  points.reserve(out.nodes.size());
  for (NodeId n : out.nodes) points.push_back(points_[n.idx()]);
  std::vector<typename M::CellNodes> cells;
  cells.reserve(out.cells.size());
  out.in_set.assign(out.cells.size(), 0);
  for (std::size_t i = 0; i < out.cells.size(); ++i) {
    typename M::CellNodes local = cells_[out.cells[i].idx()];
    for (NodeId& n : local) {
      const auto it = std::lower_bound(out.nodes.begin(), out.nodes.end(), n);
      n = NodeId(static_cast<index_t>(it - out.nodes.begin()));
    }
    cells.push_back(local);
    out.in_set[CellId(static_cast<index_t>(i))] =
        std::binary_search(set.begin(), set.end(), out.cells[i]);
  }
  out.mesh = M(std::move(points), std::move(cells));
  return out;
}

template <class M>
std::vector<NodeId> EditableMesh<M>::splice(const CavityPatch<M>& patch, const PillowResult<M>& p) {
  const std::size_t n_local = patch.nodes.size();
  std::vector<NodeId> global(static_cast<std::size_t>(p.mesh.n_nodes()));
  for (NodeId v : id_range<NodeId>(p.mesh.n_nodes())) {
    if (v.idx() < n_local) {
      global[v.idx()] = patch.nodes[v.idx()];
    } else {
      global[v.idx()] = NodeId(n_nodes());
      points_.emplace_back();
      node_cells_.emplace_back();
    }
    points_[global[v.idx()].idx()] = p.mesh.point(v);
  }
  auto to_global = [&](typename M::CellNodes nodes) {
    for (NodeId& n : nodes) n = global[n.idx()];
    return nodes;
  };
  for (CellId c : id_range<CellId>(static_cast<index_t>(patch.cells.size()))) {
    if (!patch.in_set[c]) continue;
    const CellId g = patch.cells[c.idx()];
    const typename M::CellNodes now = to_global(p.mesh.cell_nodes(c));
    typename M::CellNodes& was = cells_[g.idx()];
    for (NodeId n : was)
      if (!holds(now, n)) erase_sorted(node_cells_[n.idx()], g);
    for (NodeId n : now)
      if (!holds(was, n)) insert_sorted(node_cells_[n.idx()], g);
    was = now;
  }
  for (index_t k = static_cast<index_t>(patch.cells.size()); k < p.mesh.n_cells(); ++k) {
    const CellId g(n_cells());
    cells_.push_back(to_global(p.mesh.cell_nodes(CellId(k))));
    for (NodeId n : cells_.back()) node_cells_[n.idx()].push_back(g);
  }
  return global;
}

template <class M>
M EditableMesh<M>::build() const {
  return M(points_, cells_);
}

template class EditableMesh<QuadMesh>;
template class EditableMesh<HexMesh>;

}  // namespace hexadapt::detail
