// Small reconstruction inputs built in code: fractions of analytic shapes sampled on
// Cartesian and jittered grids, and the helpers the reconstruction tests share.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::testcase {

/// Material at a point.
using Shape = std::function<int(const Vec3&)>;

template <class M>
struct Case {
  M mesh;
  Fractions fractions;
  CellMaterials majority;
};

// Fractions by s^d samples per cell, weighted by the Jacobian of the cell map so that
// jittered cells get area-true fractions.
template <class M>
Fractions sample_fractions(const M& mesh, int n_materials, const Shape& shape,
                           int s = M::dim == 3 ? 10 : 24) {
  std::vector<std::string> names;
  for (int m = 0; m < n_materials; ++m) names.push_back("m" + std::to_string(m));
  Fractions f(mesh.n_cells(), names);
  const int sk = M::dim == 3 ? s : 1;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const auto x = mesh.cell_points(c);
    std::vector<double> w(static_cast<std::size_t>(n_materials), 0.0);
    double total = 0;
    for (int k = 0; k < sk; ++k)
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const double u = (i + 0.5) / s, v = (j + 0.5) / s, t = M::dim == 3 ? (k + 0.5) / s : 0;
          Vec3 p, du, dv;
          double jac;
          if constexpr (M::dim == 2) {
            p = (1 - u) * (1 - v) * x[0] + u * (1 - v) * x[1] + u * v * x[2] + (1 - u) * v * x[3];
            du = (1 - v) * (x[1] - x[0]) + v * (x[2] - x[3]);
            dv = (1 - u) * (x[3] - x[0]) + u * (x[2] - x[1]);
            jac = du.x() * dv.y() - du.y() * dv.x();
          } else {
            p = Vec3::Zero();
            for (int b = 0; b < 8; ++b)
              p += ((b & 1) ? u : 1 - u) * ((b & 2) ? v : 1 - v) * ((b & 4) ? t : 1 - t) *
                   x[static_cast<std::size_t>(b)];
            jac = 1;  // 3D test grids are Cartesian
          }
          w[static_cast<std::size_t>(shape(p))] += jac;
          total += jac;
        }
    for (int m = 0; m < n_materials; ++m) f(c, m) = w[static_cast<std::size_t>(m)] / total;
  }
  return f;
}

template <class M>
Case<M> make_case(M mesh, int n_materials, const Shape& shape) {
  Case<M> c{std::move(mesh), {}, {}};
  c.fractions = sample_fractions(c.mesh, n_materials, shape);
  for (CellId id : id_range<CellId>(c.mesh.n_cells()))
    c.majority.push_back(c.fractions.majority(id));
  return c;
}

/// nx x ny unit quads, interior nodes moved by up to `jitter` cell widths (deterministic).
inline QuadMesh jittered_grid(int nx, int ny, double jitter) {
  std::vector<Vec3> pts;
  unsigned state = 12345u;
  auto rnd = [&] {
    state = state * 1103515245u + 12345u;
    return ((state >> 8) & 0xFFFF) / 65535.0 * 2 - 1;
  };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool inner = i > 0 && j > 0 && i < nx && j < ny;
      const double dx = inner ? jitter * rnd() : 0, dy = inner ? jitter * rnd() : 0;
      pts.emplace_back(i + dx, j + dy, 0);
    }
  return make_quad_grid(nx, ny, std::move(pts));
}

/// Disk of material 1 in material 0.
inline Shape disk(double cx, double cy, double r) {
  return [=](const Vec3& p) { return std::hypot(p.x() - cx, p.y() - cy) < r ? 1 : 0; };
}

/// The 5x5 three-material case: a bottom strip (2), a disk above it (1), the rest (0), with
/// two triple points (in the spirit of the paper's Figs. 6-7, whose exact data is not given).
inline Case<QuadMesh> five_by_five() {
  return make_case(make_quad_grid(5, 5), 3, [](const Vec3& p) {
    if (p.y() < 1.3 + 0.15 * p.x()) return 2;
    return std::hypot(p.x() - 2.4, p.y() - 2.8) < 1.45 ? 1 : 0;
  });
}

/// Sphere of material 1 in an n^3 Cartesian grid.
inline Case<HexMesh> sphere(int n, double r) {
  const double c = 0.5 * n;
  return make_case(make_hex_grid(n, n, n), 2,
                   [=](const Vec3& p) { return (p - Vec3(c, c, c)).norm() < r ? 1 : 0; });
}

/// Volume of each material per block, from the pixel labels.
inline std::vector<double> block_volumes(const reconstruct::PixelMesh& px, index_t b) {
  std::vector<double> v(static_cast<std::size_t>(px.n_materials()), 0.0);
  for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p)
    if (px.label(p) >= 0) v[static_cast<std::size_t>(px.label(p))] += px.volume(p);
  return v;
}

/// Largest gap, in pixel volumes, between a block's material volumes and its fractions.
inline double worst_gap_in_pixels(const reconstruct::PixelMesh& px, const Fractions& f) {
  double worst = 0;
  for (index_t b = 0; b < px.n_blocks(); ++b) {
    if (!px.block_free(b)) continue;
    const auto v = block_volumes(px, b);
    double total = 0, pixel = 0;
    for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p) {
      total += px.volume(p);
      pixel = std::max(pixel, px.volume(p));
    }
    for (int m = 0; m < px.n_materials(); ++m)
      worst = std::max(
          worst, std::abs(v[static_cast<std::size_t>(m)] - f(px.block_cell(b), m) * total) / pixel);
  }
  return worst;
}

}  // namespace hexadapt::testcase
