// An independent manifold checker for the assignment tests (a different code path from
// assign/manifold.h): the link criterion. Around node n each cell contributes one corner;
// the corners of material m must form one disk (or the whole link). Computed with
//  - connected components of m's cells through faces containing n,
//  - connected components of the other cells plus "outside the domain" through those faces,
//  - in 3D, around every edge through n, m's cells must form one run.
// Cells meeting n only, or only along an edge through n, then fail, inside or on the
// domain boundary alike (the policy documented in manifold.h).
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::test {

struct UnionFind {
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int find(int a) {
    while (parent[static_cast<std::size_t>(a)] != a)
      a = parent[static_cast<std::size_t>(a)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  }
  void join(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
  std::vector<int> parent;
};

template <class M>
bool face_has(const M& mesh, CellId c, int lf, NodeId v) {
  for (NodeId x : mesh.face_nodes(c, lf))
    if (x == v) return true;
  return false;
}

template <class M>
int count_roots(UnionFind& uf, const std::vector<int>& members) {
  std::vector<int> roots;
  for (int i : members) roots.push_back(uf.find(i));
  std::sort(roots.begin(), roots.end());
  return static_cast<int>(std::unique(roots.begin(), roots.end()) - roots.begin());
}

/// Is the set of ball cells `in` (flags per node_cells(n) entry) manifold at n?
template <class M>
bool link_manifold(const M& mesh, NodeId n, const std::vector<char>& in) {
  const auto around = mesh.node_cells(n);
  const int k = static_cast<int>(around.size());
  auto local = [&](CellId c) {
    for (int i = 0; i < k; ++i)
      if (around[static_cast<std::size_t>(i)] == c) return i;
    return -1;
  };
  std::vector<int> inside, outside_set;
  for (int i = 0; i < k; ++i) (in[static_cast<std::size_t>(i)] ? inside : outside_set).push_back(i);
  if (inside.empty()) return true;
  const int outside = k;  // the region beyond the domain boundary
  UnionFind uf(k + 1);
  bool touches_outside = false;
  for (int i = 0; i < k; ++i) {
    const CellId c = around[static_cast<std::size_t>(i)];
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      if (!face_has(mesh, c, lf, n)) continue;
      const int j = local(mesh.neighbour(c, lf));
      const bool ci = in[static_cast<std::size_t>(i)];
      if (j < 0) {
        touches_outside = true;
        if (!ci) uf.join(i, outside);
      } else if (ci == static_cast<bool>(in[static_cast<std::size_t>(j)])) {
        uf.join(i, j);
      }
    }
  }
  if (count_roots<M>(uf, inside) != 1) return false;
  std::vector<int> rest = outside_set;
  if (touches_outside) rest.push_back(outside);
  if (count_roots<M>(uf, rest) > 1) return false;
  if constexpr (M::dim == 3) {
    // Every edge (n, v): m's cells around it must form one run.
    for (int i = 0; i < k; ++i)
      for (NodeId v : mesh.cell_nodes(around[static_cast<std::size_t>(i)])) {
        if (v == n) continue;
        std::vector<int> fan;
        for (int j = 0; j < k; ++j) {
          const auto cn = mesh.cell_nodes(around[static_cast<std::size_t>(j)]);
          if (std::find(cn.begin(), cn.end(), v) != cn.end() && in[static_cast<std::size_t>(j)])
            fan.push_back(j);
        }
        if (fan.size() < 2) continue;
        UnionFind f(k);
        for (int j : fan) {
          const CellId c = around[static_cast<std::size_t>(j)];
          for (int lf = 0; lf < M::faces_per_cell; ++lf) {
            if (!face_has(mesh, c, lf, n) || !face_has(mesh, c, lf, v)) continue;
            const int o = local(mesh.neighbour(c, lf));
            if (o >= 0 && in[static_cast<std::size_t>(o)]) f.join(j, o);
          }
        }
        if (count_roots<M>(f, fan) != 1) return false;
      }
  }
  return true;
}

/// Material m at node n under `labels`.
template <class M>
bool link_manifold(const M& mesh, NodeId n, const CellMaterials& labels, int m) {
  std::vector<char> in;
  for (CellId c : mesh.node_cells(n)) in.push_back(labels[c] == m);
  return link_manifold(mesh, n, in);
}

/// Number of (node, material) pairs that are not manifold.
template <class M>
int count_non_manifold(const M& mesh, const CellMaterials& labels, int n_materials) {
  int bad = 0;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    for (int m = 0; m < n_materials; ++m) bad += !link_manifold(mesh, n, labels, m);
  return bad;
}

}  // namespace hexadapt::test
