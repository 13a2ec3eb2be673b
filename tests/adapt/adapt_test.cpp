#include "hexadapt/adapt/adapt.h"

#include <gtest/gtest.h>

#include "adapt/flow_cases.h"
#include "adapt/generated_case.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {
namespace {

template <class M>
AdaptResult<M> run_base(const M& mesh, const test::Shape& shape, int n_materials, int samples) {
  const Fractions f = test::sample_fractions(mesh, shape, n_materials, samples);
  AdaptOptions o;
  o.method = AdaptMethod::base;
  return adapt(mesh, f, majority_materials(f), o);
}

// What every base result must satisfy, good quality or not.
template <class M>
void check_result(const M& grid, const AdaptResult<M>& r) {
  const auto nn = static_cast<std::size_t>(r.mesh.n_nodes());
  ASSERT_EQ(r.material.size(), static_cast<std::size_t>(r.mesh.n_cells()));
  ASSERT_EQ(r.target.size(), nn);
  ASSERT_EQ(r.distance.size(), nn);
  EXPECT_GT(r.mesh.n_cells(), grid.n_cells());
  test::check_conformal_ball(r.mesh);
  ASSERT_EQ(r.steps.size(), 4u);
  EXPECT_EQ(r.steps[0].name, "targets");
  EXPECT_EQ(r.steps[1].name, "move");
  EXPECT_EQ(r.steps[2].name, "pillow");
  EXPECT_EQ(r.steps[3].name, "smooth");
  EXPECT_EQ(r.steps[3].cells, r.mesh.n_cells());
  EXPECT_EQ(r.min_quality, min_quality(r.mesh));
  EXPECT_EQ(r.steps[3].min_quality, r.min_quality);
  // The smoothing never lowers the minimum the pillowing left.
  EXPECT_GE(r.steps[3].min_quality, r.steps[2].min_quality);
  // Direct move: every interface node sits on its target, and stays there.
  EXPECT_EQ(r.dist_init, 0.0);
  EXPECT_EQ(r.dist_final, 0.0);
  EXPECT_EQ(r.n_reached, r.n_interface_nodes);
  index_t with_target = 0;
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    with_target += r.has_target[v];
    if (!r.has_target[v]) {
      EXPECT_EQ(r.target[v], r.mesh.point(v));
    }
  }
  EXPECT_EQ(with_target, r.n_interface_nodes);
  // Cells on either side of a face between materials are both layer cells.
  for (CellId c : id_range<CellId>(r.mesh.n_cells()))
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = r.mesh.neighbour(c, lf);
      if (o.valid() && r.material[o] != r.material[c]) {
        EXPECT_GE(c.value(), grid.n_cells());
      }
    }
}

// The paper's Table 1 "base algo" column: the base method is unreliable, below the 0.3
// threshold at some resolutions and fine at others. Measured on generated cases (min scaled
// Jacobian after the direct move / after pillowing / at the end): triple point 35x15 at
// t = 2: -0.313 / 0.013 / 0.283 (0.273 at 42x18), but 0.395 at 70x30; stir 28x14 at t = 2:
// -0.459 / -0.144 / 0.288, but 0.542 at t = 1; the extruded triple point 35x15x3 at t = 2:
// -0.457 / -0.322 / -0.009 (inverted; -0.017 at 42x18x3), 0.418 at 56x24x3.
void expect_base_falls_below(const test::GeneratedCase& c, double below) {
  test::with_generated_case(
      c, [&](const auto& grid, const Fractions& f, const IdVector<CellId, int>& material) {
        AdaptOptions o;
        o.method = AdaptMethod::base;
        const auto r = adapt(grid, f, material, o);
        check_result(grid, r);
        EXPECT_LT(r.steps[1].min_quality, 0.0);  // the direct move inverts cells
        EXPECT_LT(r.min_quality, below);
        EXPECT_GT(r.n_below_threshold, 0);
      });
}

TEST(BaseMethod, TriplePointFallsBelowTheThresholdAtSomeResolution) {
  expect_base_falls_below({"triple-point", {35, 15}, 2.0}, 0.3);
}

TEST(BaseMethod, StirFallsBelowTheThresholdAtSomeTime) {
  expect_base_falls_below({"stir", {28, 14}, 2.0}, 0.3);
}

TEST(BaseMethod, ExtrudedTriplePointInvertsCells) {
  expect_base_falls_below({"triple-point", {35, 15}, 2.0, 3}, 0.0);
}

TEST(BaseMethod, SmoothsASimpleDiskToGoodQuality) {
  const QuadMesh grid = make_quad_grid(16, 16);
  const auto r = run_base(
      grid, [](const Vec3& p) { return (p - Vec3(8.2, 7.9, 0)).norm() < 5.1; }, 2, 12);
  check_result(grid, r);
  EXPECT_GT(r.min_quality, 0.4);
  EXPECT_EQ(r.n_inverted, 0);
}

TEST(BaseMethod, GivesTheSameMeshWhateverTheThreadCount) {
  // Large enough that the colour classes of the move and the smoothing run on threads.
  const QuadMesh grid = make_quad_grid(64, 40);
  const Fractions f = test::sample_fractions(
      grid,
      [](const Vec3& p) {
        return static_cast<int>(std::floor((p.x() + 2.0 * std::sin(0.3 * p.y())) / 4.1)) % 3;
      },
      3, 4);
  AdaptOptions o;
  o.method = AdaptMethod::base;
  set_threads(1);
  const auto a = adapt(grid, f, majority_materials(f), o);
  set_threads(2);
  const auto b = adapt(grid, f, majority_materials(f), o);
  set_threads(0);
  ASSERT_EQ(a.mesh.n_nodes(), b.mesh.n_nodes());
  for (NodeId v : id_range<NodeId>(a.mesh.n_nodes())) ASSERT_EQ(a.mesh.point(v), b.mesh.point(v));
  EXPECT_EQ(a.material.raw(), b.material.raw());
}

TEST(Adapt, RejectsBadOptions) {
  const QuadMesh grid = make_quad_grid(4, 4);
  const Fractions f = test::sample_fractions(
      grid, [](const Vec3& p) { return p.x() < 1.5; }, 2, 4);
  AdaptOptions o;
  EXPECT_EQ(o.method, AdaptMethod::guaranteed);
  o.method = AdaptMethod::base;
  o.move.steps = 0;
  EXPECT_THROW(adapt(grid, f, majority_materials(f), o), OptionError);
  EXPECT_EQ(parse_adapt_method("base"), AdaptMethod::base);
  EXPECT_THROW(parse_adapt_method("sculpt"), OptionError);
}

}  // namespace
}  // namespace hexadapt
