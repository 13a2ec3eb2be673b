// Volumes against the analytic ones. Two error bounds for the midpoint rule on an s x s (x s)
// sample lattice per cell, sub-cell size delta = h / s:
//  - rigorous: a misclassified sub-cell lies within its half-diagonal r = delta sqrt(d) / 2
//    of the interface, so |error| <= the volume of the tube of radius r around it
//    (circle: 4 pi R r; sphere: 4/3 pi ((R + r)^3 - (R - r)^3));
//  - statistical (used where the interface length is not known, e.g. after a flow): each
//    boundary sub-cell errs by at most delta^d, independently, so |error| <= 6 sigma with
//    sigma = delta^d sqrt(N_b / 12) and N_b = 2 s^(d-1) n_mixed boundary sub-cells.
#include "hexadapt/generate/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/generate/cases.h"
#include "hexadapt/generate/generate.h"
#include "hexadapt/generate/jitter.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::generate {
namespace {

constexpr double pi = 3.141592653589793;

double statistical_bound(const GenerateResult& r, double h, int s) {
  const double delta = h / s;
  const double nb = 2.0 * std::pow(s, r.dim - 1) * r.mixed_cells;
  return 6 * std::pow(delta, r.dim) * std::sqrt(nb / 12);
}

GenerateResult run(const std::string& name, std::vector<int> dims, int samples,
                   std::optional<double> time = std::nullopt) {
  GenerateOptions o;
  o.case_name = name;
  o.dims = std::move(dims);
  o.samples = samples;
  o.time = time;
  return generate(o);
}

TEST(Sampling, DiskAreaWithinTheSamplingError) {
  const auto r = run("disk", {64, 64}, 4);
  const double radius = 0.31, delta = 1.0 / 256, tube = 4 * pi * radius * delta * std::sqrt(2) / 2;
  const double err = std::abs(r.volumes[1] - pi * radius * radius);
  EXPECT_LT(err, tube);
  EXPECT_LT(err, statistical_bound(r, 1.0 / 64, 4));
  EXPECT_NEAR(r.volumes[0] + r.volumes[1], 1.0, 1e-12);
}

TEST(Sampling, SphereVolumeWithinTheSamplingError) {
  const auto r = run("sphere", {24, 24, 24}, 4);
  const double radius = 0.31, rr = (1.0 / 96) * std::sqrt(3) / 2;
  const double tube = 4.0 / 3 * pi * (std::pow(radius + rr, 3) - std::pow(radius - rr, 3));
  const double err = std::abs(r.volumes[1] - 4.0 / 3 * pi * std::pow(radius, 3));
  EXPECT_LT(err, tube);
  EXPECT_LT(err, statistical_bound(r, 1.0 / 24, 4));
}

TEST(Sampling, TriplePointRegionsAre3And9And9) {
  const auto r0 = run("triple-point", {70, 30}, 2, 0.0);  // interfaces on grid lines: exact
  EXPECT_NEAR(r0.volumes[0], 3, 1e-9);
  EXPECT_NEAR(r0.volumes[1], 9, 1e-9);
  EXPECT_NEAR(r0.volumes[2], 9, 1e-9);
  EXPECT_EQ(r0.mixed_cells, 0);
  for (double t : {0.5, 1.0, 2.0}) {
    const auto r = run("triple-point", {70, 30}, 4, t);
    const double bound = statistical_bound(r, 0.1, 4);
    EXPECT_GT(r.mixed_cells, 0);
    EXPECT_NEAR(r.volumes[0], 3, bound) << t;
    EXPECT_NEAR(r.volumes[1], 9, bound) << t;
    EXPECT_NEAR(r.volumes[2], 9, bound) << t;
  }
}

// Divergence-free flows keep every material's volume. Bound: the rigorous tube bound of the
// initial interfaces (their straight, lattice-aligned parts keep a systematic error) plus the
// statistical bound of the deformed state.
TEST(Sampling, FlowsPreserveVolumes) {
  struct C {
    const char* name;
    std::vector<int> dims;
    int s;
    std::vector<double> exact;
    double interface;  // length (2D) or area (3D) of the initial interfaces
  };
  const double disk = pi * 0.15 * 0.15, drop = pi * 0.13 * 0.13;
  const double ball = 4.0 / 3 * pi * std::pow(0.15, 3), drop3 = 4.0 / 3 * pi * std::pow(0.13, 3);
  for (const C& c :
       {C{"vortex", {32, 32}, 4, {1 - disk, disk}, 2 * pi * 0.15},
        C{"stir", {64, 32}, 4, {2.0 / 3, 2.0 / 3, 2.0 / 3}, 4.0},
        C{"balldrop", {32, 32}, 4, {0.65 - drop, 0.35, drop}, 1 + 2 * pi * 0.13},
        C{"vortex", {10, 10, 10}, 3, {1 - ball, ball}, 4 * pi * 0.15 * 0.15},
        C{"balldrop", {10, 10, 10}, 3, {0.65 - drop3, 0.35, drop3}, 1 + 4 * pi * 0.13 * 0.13}}) {
    const double h = 1.0 / c.dims[1], delta = h / c.s;
    const double tube = 1.01 * delta * std::sqrt(static_cast<double>(c.dims.size())) * c.interface;
    for (double t : {0.0, 0.7}) {
      const auto r = run(c.name, c.dims, c.s, t);
      EXPECT_EQ(r.steps > 0, t > 0);
      const double bound = tube + statistical_bound(r, h, c.s);
      for (std::size_t m = 0; m < r.volumes.size(); ++m)
        EXPECT_NEAR(r.volumes[m], c.exact[m], bound) << c.name << " t " << t << " m " << m;
    }
  }
}

TEST(Sampling, FractionsSumToExactlyOne) {
  for (const auto& c : cases()) {
    const int dim = c.default_dim();
    const auto r = run(c.name, dim == 2 ? std::vector<int>{20, 14} : std::vector<int>{9, 8, 7}, 3);
    const auto& cd = r.data.cell_data;
    ASSERT_EQ(cd.size(), c.materials.size());
    for (std::size_t i = 0; i < cd[0].values.size(); ++i) {
      double forward = 0, backward = 0;
      for (std::size_t m = 0; m < cd.size(); ++m) {
        forward += cd[m].values[i];
        backward += cd[cd.size() - 1 - m].values[i];
        ASSERT_GE(cd[m].values[i], 0.0);
      }
      ASSERT_EQ(forward, 1.0) << c.name << " cell " << i;
      ASSERT_EQ(backward, 1.0) << c.name << " cell " << i;
    }
  }
}

// Cells whose centre is farther from the circle than their half-diagonal are exactly pure,
// on the right side (checked with the analytic distance, not the layout).
TEST(Sampling, CellsFarFromTheInterfaceArePure) {
  const auto r = run("disk", {40, 40}, 5);
  const auto* in = r.data.find_cell_array("vf_disk");
  const auto* out = r.data.find_cell_array("vf_outside");
  ASSERT_TRUE(in && out);
  int far = 0;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      const Vec3 c((i + 0.5) / 40, (j + 0.5) / 40, 0);
      const double d = (c - Vec3(0.48, 0.53, 0)).norm() - 0.31;
      if (std::abs(d) <= std::sqrt(2) / 80) continue;
      ++far;
      const std::size_t k = static_cast<std::size_t>(i + 40 * j);
      EXPECT_EQ(in->values[k], d < 0 ? 1.0 : 0.0);
      EXPECT_EQ(out->values[k], d < 0 ? 0.0 : 1.0);
    }
  EXPECT_GT(far, 1200);
  EXPECT_GT(r.mixed_cells, 50);
}

TEST(Sampling, ShortcutGivesTheSameFractionsAsFullSampling) {
  for (const char* name : {"disk", "triple-point", "balldrop"}) {
    const Case& c = find_case(name);
    const Scene scene = c.build(2, 1);
    const io::MeshData mesh =
        io::from_mesh(make_quad_grid(24, 20, Vec3::Zero(), Vec3(0.3, 0.15, 1)));
    SamplingOptions o;
    o.samples = 3;
    o.time = 0.7;
    const auto fast = sample_fractions(mesh, scene, c.materials, o);
    o.shortcut = false;
    const auto full = sample_fractions(mesh, scene, c.materials, o);
    EXPECT_GT(fast.shortcut_cells, 0) << name;
    EXPECT_EQ(full.shortcut_cells, 0);
    for (CellId cell : id_range<CellId>(mesh.n_cells()))
      for (int m = 0; m < fast.fractions.n_materials(); ++m)
        ASSERT_EQ(fast.fractions(cell, m), full.fractions(cell, m)) << name;
  }
}

TEST(Sampling, SameResultWhateverTheThreadCount) {
  std::vector<std::vector<double>> results;
  for (int threads : {1, 2, 3}) {
    set_threads(threads);
    const auto r = run("triple-point", {70, 30}, 3, 1.0);
    std::vector<double> all;
    for (const auto& a : r.data.cell_data) all.insert(all.end(), a.values.begin(), a.values.end());
    results.push_back(all);
  }
  set_threads(0);
  EXPECT_EQ(results[0], results[1]);
  EXPECT_EQ(results[0], results[2]);
}

// Jittered (non-affine) cells take the multilinear path with Jacobian weights: the disk
// area stays within the same bound, and pure cells stay pure.
TEST(Sampling, JitteredCellsKeepTheVolume) {
  GenerateOptions o;
  o.case_name = "disk";
  o.dims = {64, 64};
  o.jitter = 0.3;
  o.samples = 4;
  const auto r = generate(o);
  EXPECT_GT(r.jitter.moved_nodes, 3000);
  const double radius = 0.31, delta = 1.0 / 256;
  // jittered sub-cells are at most (1 + 2 * 0.3) times larger per axis
  const double tube = 4 * pi * radius * 1.6 * delta * std::sqrt(2) / 2;
  EXPECT_NEAR(r.volumes[1], pi * radius * radius, tube);
  EXPECT_NEAR(r.volumes[0] + r.volumes[1], 1.0, 1e-12);
}

TEST(Sampling, RejectsBadOptions) {
  const Case& c = find_case("disk");
  const io::MeshData mesh = io::from_mesh(make_quad_grid(2, 2));
  SamplingOptions o;
  o.samples = 0;
  EXPECT_THROW(sample_fractions(mesh, c.build(2, 1), c.materials, o), OptionError);
}

}  // namespace
}  // namespace hexadapt::generate
