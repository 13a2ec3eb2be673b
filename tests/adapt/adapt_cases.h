// Inputs for the adaptation tests, built in memory: fractions sampled from analytic shapes,
// the majority assignment, jittered grids and an independent conformity check.
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "hexadapt/adapt/targets.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::test {

/// The node of mesh at p (invalid when none is).
template <class M>
NodeId node_at(const M& mesh, const Vec3& p) {
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if ((mesh.point(n) - p).norm() < 1e-12) return n;
  return NodeId();
}

/// Targets with one node, the one at `from`, heading for `to`.
template <class M>
Targets one_target(const M& mesh, const Vec3& from, const Vec3& to) {
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  Targets t;
  t.has.assign(nn, 0);
  t.position = IdVector<NodeId, Vec3>(nn, Vec3::Zero());
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) t.position[n] = mesh.point(n);
  t.interface.resize(nn);
  const NodeId moving = node_at(mesh, from);
  t.has[moving] = 1;
  t.position[moving] = to;
  return t;
}

/// Material of a point in space.
using Shape = std::function<int(const Vec3&)>;

/// Point of cell c at reference coordinates u in [0,1]^dim (bilinear / trilinear map).
template <class M>
Vec3 cell_map(const M& mesh, CellId c, const Vec3& u) {
  const auto p = mesh.cell_points(c);
  if constexpr (M::dim == 2) {
    return (1 - u.x()) * (1 - u.y()) * p[0] + u.x() * (1 - u.y()) * p[1] + u.x() * u.y() * p[2] +
           (1 - u.x()) * u.y() * p[3];
  } else {
    Vec3 s = Vec3::Zero();
    for (int b = 0; b < 8; ++b)
      s += ((b & 1) ? u.x() : 1 - u.x()) * ((b & 2) ? u.y() : 1 - u.y()) *
           ((b & 4) ? u.z() : 1 - u.z()) * p[static_cast<std::size_t>(b)];
    return s;
  }
}

/// Fractions by sampling s^dim points per cell (uniform in reference coordinates).
template <class M>
Fractions sample_fractions(const M& mesh, const Shape& shape, int n_materials, int s = 16) {
  std::vector<std::string> names;
  for (int m = 0; m < n_materials; ++m) names.push_back("m" + std::to_string(m));
  Fractions f(mesh.n_cells(), names);
  const int sz = M::dim == 3 ? s : 1;
  const double w = 1.0 / (s * s * sz);
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int k = 0; k < sz; ++k)
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const Vec3 u((i + 0.5) / s, (j + 0.5) / s, M::dim == 3 ? (k + 0.5) / s : 0.0);
          f(c, shape(cell_map(mesh, c, u))) += w;
        }
  return f;
}

/// Moves every interior node of a structured grid by up to `amount` per axis (seeded).
inline std::vector<Vec3> jittered_points(int nx, int ny, int nz, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  std::vector<Vec3> p;
  for (int k = 0; k <= std::max(nz, 0); ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        Vec3 x(i, j, k);
        const double dx = u(rng), dy = u(rng), dz = u(rng);
        if (i > 0 && i < nx) x.x() += dx;
        if (j > 0 && j < ny) x.y() += dy;
        if (nz > 0 && k > 0 && k < nz) x.z() += dz;
        p.push_back(x);
      }
  return p;
}

/// Independent conformity check from the cell lists alone: every face (edge in 2D) is used
/// once or twice, and the Euler characteristic is that of a ball (1). Returns the number of
/// faces used once.
template <class M>
std::size_t check_conformal_ball(const M& mesh) {
  std::map<std::vector<NodeId>, int> faces;
  std::set<std::pair<NodeId, NodeId>> edges;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const auto fn = mesh.face_nodes(c, lf);
      std::vector<NodeId> key(fn.begin(), fn.end());
      for (std::size_t i = 0; i < key.size(); ++i) {
        NodeId a = key[i], b = key[(i + 1) % key.size()];
        if (b < a) std::swap(a, b);
        edges.insert({a, b});
      }
      std::sort(key.begin(), key.end());
      ++faces[key];
    }
  }
  std::size_t once = 0;
  for (const auto& [key, count] : faces) {
    EXPECT_LE(count, 2) << "a face shared by more than two cells";
    once += count == 1;
  }
  const long v = mesh.n_nodes(), e = static_cast<long>(edges.size()),
             f = static_cast<long>(faces.size()), c = mesh.n_cells();
  if constexpr (M::dim == 2) {
    EXPECT_EQ(v - e + c, 1) << "Euler characteristic of a disk";
  } else {
    EXPECT_EQ(v - e + f - c, 1) << "Euler characteristic of a ball";
  }
  return once;
}

}  // namespace hexadapt::test
