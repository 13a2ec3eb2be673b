// Inputs shared by the assignment tests: random fractions and renumbered meshes.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::test {

/// Each cell mixes a random subset of at most `mix` of `n_materials` materials.
inline Fractions random_fractions(index_t n_cells, int n_materials, int mix, unsigned seed) {
  std::vector<std::string> names;
  for (int m = 0; m < n_materials; ++m) names.push_back("m" + std::to_string(m));
  Fractions f(n_cells, names);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, n_materials - 1), count(1, mix);
  std::uniform_real_distribution<double> w(0.05, 1.0);
  for (CellId c : id_range<CellId>(n_cells)) {
    const int k = count(rng);
    std::vector<std::pair<int, double>> parts;
    double sum = 0;
    for (int i = 0; i < k; ++i) parts.emplace_back(pick(rng), w(rng));
    for (auto& p : parts) sum += p.second;
    for (auto& p : parts) f(c, p.first) += p.second / sum;
  }
  return f;
}

/// Fractions of disks/spheres (material i inside ball i, the last material outside),
/// by sampling s^d points per cell of a unit-spaced grid: realistic interfaces.
template <class M>
Fractions ball_fractions(const M& mesh, const std::vector<std::pair<Vec3, double>>& balls,
                         int s = 4) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i <= balls.size(); ++i) names.push_back("m" + std::to_string(i));
  Fractions f(mesh.n_cells(), names);
  const int sz = M::dim == 3 ? s : 1;
  const double w = 1.0 / (s * s * sz);
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const auto nodes = mesh.cell_nodes(c);
    const Vec3 lo = mesh.point(nodes[0]);
    for (int a = 0; a < s; ++a)
      for (int b = 0; b < s; ++b)
        for (int d = 0; d < sz; ++d) {
          const Vec3 p = lo + Vec3((a + 0.5) / s, (b + 0.5) / s, M::dim == 3 ? (d + 0.5) / s : 0);
          std::size_t m = balls.size();
          for (std::size_t i = 0; i < balls.size(); ++i)
            if ((p - balls[i].first).norm() < balls[i].second) {
              m = i;
              break;
            }
          f(c, static_cast<int>(m)) += w;
        }
  }
  return f;
}

/// Structured points of an nx x ny (x nz) grid, each (the boundary too) moved by up to
/// `amount` in each direction.
inline std::vector<Vec3> all_points_jittered(int nx, int ny, int nz, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> j(-amount, amount);
  std::vector<Vec3> p;
  for (int k = 0; k <= nz; ++k)
    for (int y = 0; y <= ny; ++y)
      for (int x = 0; x <= nx; ++x)
        p.emplace_back(x + j(rng), y + j(rng), nz > 0 ? k + j(rng) : 0.0);
  return p;
}

}  // namespace hexadapt::test
