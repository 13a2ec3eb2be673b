// Time and peak memory of the greedy reconstruction (pixels, assignment, metrics, model) on
// the two sizes of the issue: a 420x180x3 triple-point-like grid and a 128^3 sphere. The
// fractions are built analytically here (cells far from an interface are pure, the others
// sampled), so the bench does not depend on the generator.
//   reconstruct_bench triple|sphere [nsub] [threads]
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "hexadapt/core/parallel.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"
#include "hexadapt/reconstruct/reconstruct.h"

namespace {

using namespace hexadapt;

// Material at a point, and a bound on the distance below which a cell may be mixed.
struct Shape {
  int n_materials;
  std::function<int(const Vec3&)> at;
  std::function<bool(const Vec3& centre)> maybe_mixed;
};

Fractions fractions(const HexMesh& mesh, const Shape& s, int samples) {
  std::vector<std::string> names;
  for (int m = 0; m < s.n_materials; ++m) names.push_back("m" + std::to_string(m));
  Fractions f(mesh.n_cells(), names);
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    const auto x = mesh.cell_points(c);
    const Vec3 lo = x[0], hi = x[7];
    if (!s.maybe_mixed(0.5 * (lo + hi))) {
      f(c, s.at(0.5 * (lo + hi))) = 1;
      return;
    }
    std::vector<int> count(static_cast<std::size_t>(s.n_materials), 0);
    for (int k = 0; k < samples; ++k)
      for (int j = 0; j < samples; ++j)
        for (int l = 0; l < samples; ++l) {
          const Vec3 t((l + 0.5) / samples, (j + 0.5) / samples, (k + 0.5) / samples);
          ++count[static_cast<std::size_t>(s.at(lo + (hi - lo).cwiseProduct(t)))];
        }
    const double n = samples * samples * samples;
    for (int m = 0; m < s.n_materials; ++m) f(c, m) = count[static_cast<std::size_t>(m)] / n;
  });
  return f;
}

// Three regions of the triple-point problem on [0,7]x[0,3], interfaces made wavy so that
// they cross cells at every angle.
Shape triple_point() {
  auto left = [](const Vec3& p) { return p.x() < 1 + 0.25 * std::sin(2.1 * p.y()); };
  auto low = [](const Vec3& p) { return p.y() < 1.5 + 0.3 * std::sin(1.3 * p.x()); };
  return {3, [=](const Vec3& p) { return left(p)  ? 0
                                         : low(p) ? 1
                                                  : 2; },
          [=](const Vec3& c) {
            const double h = 7.0 / 420 * 1.5;
            return std::abs(c.x() - 1 - 0.25 * std::sin(2.1 * c.y())) < 0.6 * 2.1 * h + h ||
                   std::abs(c.y() - 1.5 - 0.3 * std::sin(1.3 * c.x())) < 0.4 * h + h;
          }};
}

Shape sphere(int n) {
  const Vec3 centre(0.5 * n, 0.5 * n, 0.5 * n);
  const double r = 0.37 * n;
  return {2, [=](const Vec3& p) { return (p - centre).norm() < r ? 1 : 0; },
          [=](const Vec3& c) { return std::abs((c - centre).norm() - r) < 0.9; }};
}

long peak_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "triple";
  const int nsub = argc > 2 ? std::atoi(argv[2]) : 0;
  set_threads(argc > 3 ? std::atoi(argv[3]) : 0);
  Timer t;
  HexMesh mesh;
  Shape shape;
  if (which == "triple") {
    mesh = make_hex_grid(420, 180, 3, Vec3::Zero(), Vec3(7.0 / 420, 3.0 / 180, 3.0 / 180));
    shape = triple_point();
  } else if (which == "sphere") {
    mesh = make_hex_grid(128, 128, 128);
    shape = sphere(128);
  } else {
    std::fprintf(stderr, "usage: reconstruct_bench triple|sphere [nsub] [threads]\n");
    return 1;
  }
  const Fractions f = fractions(mesh, shape, 6);
  const CellMaterials assignment = majority_materials(f);
  const double setup = t.seconds();
  const long setup_kb = peak_kb();
  t.restart();
  reconstruct::ReconstructOptions o;
  o.pixels.nsub = nsub;
  const auto rec = reconstruct::reconstruct(mesh, f, assignment, o);
  const double run = t.seconds();
  const auto& r = rec.result;
  std::printf("case %s: %d cells, nsub %d, %lld pixels (%lld free) in %d cells\n", which.c_str(),
              mesh.n_cells(), r.plan.nsub, static_cast<long long>(r.plan.n_pixels),
              static_cast<long long>(r.plan.n_free_pixels), r.plan.n_blocks);
  std::printf("setup (grid + fractions) %.2f s, peak %.0f MB\n", setup,
              static_cast<double>(setup_kb) / 1e3);
  std::printf("reconstruct %.2f s:", run);
  for (const auto& [phase, s] : r.times) std::printf(" %s %.2f s", phase.c_str(), s);
  std::printf("\ngreedy rounds %d, fallback pixels %lld", r.greedy.rounds,
              static_cast<long long>(r.greedy.fallback_pixels));
  std::printf("\nestimate %.0f MB, peak RSS %.0f MB\n", r.plan.bytes / 1e6,
              static_cast<double>(peak_kb()) / 1e3);
  std::printf(
      "edgecut %lld, discrepancy %.6g (relative %.3g), model %zu facets %zu curves %zu corners\n",
      static_cast<long long>(r.edgecut), r.discrepancy + r.unpixelated_discrepancy,
      (r.discrepancy + r.unpixelated_discrepancy) / r.domain_volume, rec.model.facets.size(),
      rec.model.curves.size(), rec.model.corners.size());
  return 0;
}
