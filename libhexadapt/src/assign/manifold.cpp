#include "hexadapt/assign/manifold.h"

#include <algorithm>
#include <bitset>
#include <cstdint>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

using LocalSet = std::bitset<1024>;
static_assert(LocalBall<HexMesh>::max_local <= 1024, "LocalSet too small");

/// Bit i set when ball cell i is labelled m.
std::uint64_t cells_of(const std::vector<int>& labels, int m) {
  std::uint64_t s = 0;
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] == m) s |= std::uint64_t{1} << i;
  return s;
}

/// Is `cells` one piece when cell i touches the cells of next_to(i)?
template <class Next>
bool connected(std::uint64_t cells, Next next_to) {
  const std::uint64_t start = cells & (~cells + 1);  // lowest set bit
  std::uint64_t reached = start, frontier = start;
  while (frontier) {
    const int i = __builtin_ctzll(frontier);
    frontier &= frontier - 1;
    const std::uint64_t fresh = next_to(i) & cells & ~reached;
    reached |= fresh;
    frontier |= fresh;
  }
  return reached == cells;
}

template <class M>
bool face_connected(const LocalBall<M>& ball, std::uint64_t cells) {
  return connected(cells, [&](int i) {
    std::uint64_t s = 0;
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const int j = ball.face(i, lf).neighbour;
      if (j >= 0) s |= std::uint64_t{1} << j;
    }
    return s;
  });
}

/// 3D: around every edge through the node, the cells form one run.
template <class M>
bool runs_around_edges(const LocalBall<M>& ball, std::uint64_t cells) {
  for (const auto& fan : ball.fans()) {
    const std::uint64_t in = fan.cells & cells;
    if ((in & (in - 1)) == 0) continue;
    if (!connected(in, [&](int i) { return fan.next_to[static_cast<std::size_t>(i)]; }))
      return false;
  }
  return true;
}

template <class M>
int euler_of(const LocalBall<M>& ball, std::uint64_t cells) {
  LocalSet nodes, edges;
  int n_faces = 0;
  for (std::uint64_t rest = cells; rest; rest &= rest - 1) {
    const int i = __builtin_ctzll(rest);
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const auto& f = ball.face(i, lf);
      if (f.neighbour >= 0 && ((cells >> f.neighbour) & 1)) continue;  // inside the union
      ++n_faces;
      for (auto v : f.nodes) nodes.set(v);
      if constexpr (M::dim == 3)
        for (auto e : f.edges) edges.set(e);
    }
  }
  const int v = static_cast<int>(nodes.count());
  if constexpr (M::dim == 3)
    return v - static_cast<int>(edges.count()) + n_faces;
  else
    return v - n_faces;  // in 2D the boundary "faces" are edges
}

template <class M>
bool manifold_cells(const LocalBall<M>& ball, std::uint64_t cells) {
  if ((cells & (cells - 1)) == 0) return true;  // empty or a single cell
  constexpr int target = M::dim == 3 ? 2 : 0;
  return face_connected(ball, cells) && runs_around_edges(ball, cells) &&
         euler_of(ball, cells) == target;
}

template <class M>
bool uniform_around(const M& mesh, const CellMaterials& labels, NodeId n) {
  const auto cells = mesh.node_cells(n);
  for (CellId c : cells)
    if (labels[c] != labels[cells[0]]) return false;
  return true;
}

}  // namespace

template <class M>
int euler_characteristic(const LocalBall<M>& ball, const std::vector<int>& labels, int m) {
  return euler_of(ball, cells_of(labels, m));
}

template <class M>
bool is_manifold(const LocalBall<M>& ball, const std::vector<int>& labels, int m) {
  return manifold_cells(ball, cells_of(labels, m));
}

template <class M>
bool is_manifold(const LocalBall<M>& ball, const std::vector<int>& labels) {
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if ((seen >> i) & 1) continue;
    const std::uint64_t cells = cells_of(labels, labels[i]);
    seen |= cells;
    if (!manifold_cells(ball, cells)) return false;
  }
  return true;
}

template <class M>
std::vector<int> non_manifold_materials(const M& mesh, const CellMaterials& labels, NodeId n) {
  std::vector<int> bad;
  if (uniform_around(mesh, labels, n)) return bad;
  const LocalBall<M> ball(mesh, n);
  std::vector<int> local;
  for (CellId c : ball.cells()) local.push_back(labels[c]);
  std::vector<int> present = local;
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());
  for (int m : present)
    if (!is_manifold(ball, local, m)) bad.push_back(m);
  return bad;
}

namespace {

template <class M>
bool manifold_node(const M& mesh, const CellMaterials& labels, NodeId n) {
  if (uniform_around(mesh, labels, n)) return true;
  const LocalBall<M> ball(mesh, n);
  std::vector<int> local;
  for (CellId c : ball.cells()) local.push_back(labels[c]);
  return is_manifold(ball, local);
}

}  // namespace

template <class M>
std::vector<NodeId> non_manifold_among(const M& mesh, const CellMaterials& labels,
                                       std::vector<NodeId> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::vector<char> bad(nodes.size(), 0);
  auto test = [&](std::int64_t i) {
    bad[static_cast<std::size_t>(i)] =
        !manifold_node(mesh, labels, nodes[static_cast<std::size_t>(i)]);
  };
  const auto n = static_cast<std::int64_t>(nodes.size());
  if (n < 512) {  // a few microseconds of work: not worth waking the threads
    for (std::int64_t i = 0; i < n; ++i) test(i);
  } else {
    parallel_for(n, test);
  }
  std::vector<NodeId> out;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (bad[i]) out.push_back(nodes[i]);
  return out;
}

template <class M>
std::vector<NodeId> non_manifold_nodes(const M& mesh, const CellMaterials& labels) {
  std::vector<char> bad(static_cast<std::size_t>(mesh.n_nodes()), 0);
  parallel_for(mesh.n_nodes(), [&](std::int64_t i) {
    bad[static_cast<std::size_t>(i)] = !manifold_node(mesh, labels, NodeId(i));
  });
  std::vector<NodeId> out;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (bad[n.idx()]) out.push_back(n);
  return out;
}

#define HEXADAPT_INSTANTIATE(M)                                                             \
  template int euler_characteristic(const LocalBall<M>&, const std::vector<int>&, int);     \
  template bool is_manifold(const LocalBall<M>&, const std::vector<int>&, int);             \
  template bool is_manifold(const LocalBall<M>&, const std::vector<int>&);                  \
  template std::vector<int> non_manifold_materials(const M&, const CellMaterials&, NodeId); \
  template std::vector<NodeId> non_manifold_nodes(const M&, const CellMaterials&);          \
  template std::vector<NodeId> non_manifold_among(const M&, const CellMaterials&,           \
                                                  std::vector<NodeId>);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt::assign
