#include "hexadapt/generate/sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "cells.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/core/timer.h"

namespace hexadapt::generate {

namespace {

constexpr int max_materials = 16;
constexpr double quantum = 0x1.0p-40;  // fractions are multiples of this: exact sums

using Weights = std::array<double, max_materials>;

/// The cell's corners in binary lattice order (v = i + 2j + 4k) in 2D and 3D.
template <int D>
std::array<Vec3, (1 << D)> binary_corners(const io::MeshData& mesh, CellId c) {
  auto p = detail::cell_corners<D>(mesh, c.idx());
  if constexpr (D == 2) std::swap(p[2], p[3]);  // ccw 0 1 2 3 -> binary 0 1 3 2
  return p;
}

/// Multilinear map x(xi) of a cell with 2^d binary-ordered corners and its Jacobian
/// determinant (2D: the xy determinant).
template <int D>
void cell_map(const std::array<Vec3, (1 << D)>& p, const double* xi, Vec3& x, double& det) {
  x.setZero();
  Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
  for (int v = 0; v < (1 << D); ++v) {
    double w = 1;
    std::array<double, 3> dw{1, 1, 1};
    for (int a = 0; a < D; ++a) {
      const bool hi = (v >> a) & 1;
      const double f = hi ? xi[a] : 1 - xi[a];
      for (int b = 0; b < D; ++b) dw[static_cast<std::size_t>(b)] *= b == a ? (hi ? 1 : -1) : f;
      w *= f;
    }
    x += w * p[static_cast<std::size_t>(v)];
    for (int b = 0; b < D; ++b)
      jac.col(b) += dw[static_cast<std::size_t>(b)] * p[static_cast<std::size_t>(v)];
  }
  det = D == 2 ? jac(0, 0) * jac(1, 1) - jac(0, 1) * jac(1, 0) : jac.determinant();
}

/// Writes the weights of one cell as fractions: multiples of `quantum`, the largest as the
/// remainder, so that the row sums to exactly 1.
void set_row(Fractions& f, CellId c, const Weights& w, int n) {
  double total = 0;
  int largest = 0;
  for (int m = 0; m < n; ++m) {
    total += w[static_cast<std::size_t>(m)];
    if (w[static_cast<std::size_t>(m)] > w[static_cast<std::size_t>(largest)]) largest = m;
  }
  double rest = 1;
  for (int m = 0; m < n; ++m) {
    if (m == largest) continue;
    const double v = std::round(w[static_cast<std::size_t>(m)] / total / quantum) * quantum;
    f(c, m) = v;
    rest -= v;
  }
  f(c, largest) = rest;
}

/// How one cell was classified.
struct CellCounts {
  bool shortcut = false;
  bool mixed = false;
};

/// The dimension traits the sampler needs (as QuadMesh / HexMesh name them).
template <int D>
struct Dim {
  static constexpr int dim = D;
  static constexpr int nodes_per_cell = 1 << D;
};

/// Classifies the cells of one dimension M::dim; run() only writes its own cell's row.
template <class M>
class Sampler {
 public:
  Sampler(const io::MeshData& mesh, const Scene& scene, int n_materials, const SamplingOptions& o,
          int steps)
      : mesh_(mesh),
        scene_(scene),
        n_(n_materials),
        s_(o.samples),
        time_(o.time),
        steps_(steps),
        shortcut_(o.shortcut) {
    if (shortcut_ && scene_.flow && time_ != 0) traced_ = traced_points();
  }

  CellCounts run(CellId c, Fractions& out) const {
    const auto p = binary_corners<M::dim>(mesh_, c);
    Vec3 centre = Vec3::Zero();
    for (const auto& q : p) centre += q;
    centre /= static_cast<double>(p.size());
    double radius = 0;
    for (const auto& q : p) radius = std::max(radius, (q - centre).norm());
    const bool moves = moving(centre, radius);
    if (shortcut_ && !moves && scene_.layout.clearance(centre) > radius * (1 + 1e-9) + 1e-12) {
      const int m = scene_.layout.material_at(centre);
      for (int k = 0; k < n_; ++k) out(c, k) = k == m ? 1.0 : 0.0;
      return {true, false};
    }
    if (moves && !traced_.empty()) {
      const Vec3 origin = trace_back(*scene_.flow, centre, time_, steps_);
      if (scene_.layout.clearance(origin) > image_radius(c, origin)) {
        const int m = scene_.layout.material_at(origin);
        for (int k = 0; k < n_; ++k) out(c, k) = k == m ? 1.0 : 0.0;
        return {true, false};
      }
    }
    Weights w{};
    const int n_samples = ipow(s_, M::dim);
    if (is_affine(p)) {
      sample_affine(p, moves, w);
    } else {
      sample_general(p, moves, w, n_samples);
    }
    set_row(out, c, w, n_);
    return {false, !out.is_pure(c)};
  }

 private:
  /// Parallelograms (parallelepipeds): x = p0 + sum xi_a e_a, constant Jacobian, so equal
  /// weights (the common Cartesian case, without the multilinear map per sample).
  static bool is_affine(const std::array<Vec3, M::nodes_per_cell>& p) {
    const double tol = 1e-12 * ((p.back() - p.front()).norm() + 1e-300);
    if ((p[3] - p[2] - p[1] + p[0]).norm() > tol) return false;
    if constexpr (M::dim == 3)
      for (int v = 4; v < 8; ++v)
        if ((p[static_cast<std::size_t>(v)] - p[static_cast<std::size_t>(v - 4)] - p[4] + p[0])
                .norm() > tol)
          return false;
    return true;
  }
  void sample_affine(const std::array<Vec3, M::nodes_per_cell>& p, bool moves, Weights& w) const {
    std::array<Vec3, 3> e;
    for (int a = 0; a < M::dim; ++a)
      e[static_cast<std::size_t>(a)] = (p[static_cast<std::size_t>(1 << a)] - p[0]) / s_;
    std::array<int, max_materials> count{};
    const Vec3 base = p[0] + 0.5 * (e[0] + e[1] + (M::dim == 3 ? e[2] : Vec3::Zero()));
    for (int k = 0; k < (M::dim == 3 ? s_ : 1); ++k)
      for (int j = 0; j < s_; ++j)
        for (int i = 0; i < s_; ++i) {
          Vec3 x = base + i * e[0] + j * e[1];
          if constexpr (M::dim == 3) x += k * e[2];
          if (moves && !scene_.flow->still_in(x, 0)) x = trace_back(*scene_.flow, x, time_, steps_);
          ++count[static_cast<std::size_t>(scene_.layout.material_at(x))];
        }
    for (int m = 0; m < n_; ++m)
      w[static_cast<std::size_t>(m)] = count[static_cast<std::size_t>(m)];
  }
  void sample_general(const std::array<Vec3, M::nodes_per_cell>& p, bool moves, Weights& w,
                      int n_samples) const {
    for (int i = 0; i < n_samples; ++i) {
      double xi[3] = {0, 0, 0};
      for (int a = 0, r = i; a < M::dim; ++a, r /= s_) xi[a] = (r % s_ + 0.5) / s_;
      Vec3 x;
      double det;
      cell_map<M::dim>(p, xi, x, det);
      if (moves && !scene_.flow->still_in(x, 0)) x = trace_back(*scene_.flow, x, time_, steps_);
      w[static_cast<std::size_t>(scene_.layout.material_at(x))] += det;
    }
  }
  /// Every mesh point traced back to time 0 (each shared by the cells around it).
  std::vector<Vec3> traced_points() const {
    std::vector<Vec3> traced(mesh_.points.size());
    parallel_for(static_cast<std::int64_t>(traced.size()), [&](std::int64_t i) {
      const auto k = static_cast<std::size_t>(i);
      traced[k] = trace_back(*scene_.flow, mesh_.points[k], time_, steps_);
    });
    return traced;
  }
  /// A radius around `origin` (the cell's centre traced back) that holds the cell's image at
  /// time 0: the farthest traced corner with a quarter more, plus twice the distance from
  /// `origin` to the traced corners' mean, which is 0 where the flow map is affine across the
  /// cell and grows with its curvature (docs/benchmarks.md: the same fractions as sampling
  /// every cell on the cases measured).
  double image_radius(CellId c, const Vec3& origin) const {
    double r = 0;
    Vec3 mean = Vec3::Zero();
    const auto first = c.idx() * static_cast<std::size_t>(M::nodes_per_cell);
    for (std::size_t v = 0; v < static_cast<std::size_t>(M::nodes_per_cell); ++v) {
      const Vec3& p = traced_[mesh_.cells[first + v].idx()];
      r = std::max(r, (p - origin).norm());
      mean += p / M::nodes_per_cell;
    }
    return (1.25 * r + 2 * (mean - origin).norm()) * (1 + 1e-9) + 1e-12;
  }
  static int ipow(int b, int e) {
    int r = 1;
    for (int i = 0; i < e; ++i) r *= b;
    return r;
  }
  bool moving(const Vec3& centre, double radius) const {
    return scene_.flow && time_ != 0 && !scene_.flow->still_in(centre, radius);
  }

  const io::MeshData& mesh_;
  const Scene& scene_;
  int n_, s_;
  double time_;
  int steps_;
  bool shortcut_;
  std::vector<Vec3> traced_;  ///< the points traced back (a moving scene with the shortcut)
};

template <class M>
void sample_cells(const io::MeshData& mesh, const Sampler<M>& sampler, const Progress& progress,
                  Fractions& fractions, std::vector<CellCounts>& counts) {
  const std::int64_t n_cells = mesh.n_cells();
  const std::int64_t block = std::max<std::int64_t>(4096, n_cells / 64);
  for (std::int64_t begin = 0; begin < n_cells; begin += block) {
    const std::int64_t count = std::min(block, n_cells - begin);
    parallel_for(count, [&](std::int64_t i) {
      const CellId c(begin + i);
      counts[c.idx()] = sampler.run(c, fractions);
    });
    if (progress)
      progress("sampling", static_cast<double>(begin + count) / static_cast<double>(n_cells));
  }
}

}  // namespace

SamplingResult sample_fractions(const io::MeshData& mesh, const Scene& scene,
                                const std::vector<std::string>& materials,
                                const SamplingOptions& options) {
  if (options.samples < 1 || options.samples > 64)
    throw OptionError("samples per axis must be in 1..64, got " + std::to_string(options.samples));
  if (materials.empty() || materials.size() > max_materials)
    throw OptionError("a scene needs 1 to 16 materials");
  if (options.steps < 0) throw OptionError("RK4 steps must be >= 0");
  if (!std::isfinite(options.time)) throw OptionError("flow time must be a finite number");
  if (scene.layout.max_material() >= static_cast<int>(materials.size()))
    throw InternalError("the scene paints a material index beyond its material list");
  const Timer timer;
  SamplingResult res;
  const int n = static_cast<int>(materials.size());
  res.fractions = Fractions(mesh.n_cells(), materials);
  if (scene.flow && options.time != 0)
    res.steps = options.steps > 0 ? options.steps : automatic_steps(*scene.flow, options.time);
  if (mesh.dim != 2 && mesh.dim != 3) throw OptionError("sampling needs quads or hexes");
  std::vector<CellCounts> counts(static_cast<std::size_t>(mesh.n_cells()));
  if (mesh.dim == 2)
    sample_cells(mesh, Sampler<Dim<2>>(mesh, scene, n, options, res.steps), options.progress,
                 res.fractions, counts);
  else
    sample_cells(mesh, Sampler<Dim<3>>(mesh, scene, n, options, res.steps), options.progress,
                 res.fractions, counts);

  for (const auto& k : counts) {
    (k.shortcut ? res.shortcut_cells : res.sampled_cells)++;
    if (k.mixed) ++res.mixed_cells;
  }
  res.seconds = timer.seconds();
  return res;
}

}  // namespace hexadapt::generate
