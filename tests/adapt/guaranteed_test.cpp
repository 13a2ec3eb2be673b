// The guaranteed pipeline (paper Fig. 10-b) on small generated cases: every output cell keeps
// the threshold, the mesh is valid, the nodes get closer to their targets than after the
// first controlled move, and the result does not depend on the thread count.
#include <gtest/gtest.h>

#include <variant>

#include "adapt/flow_cases.h"
#include "hexadapt/adapt/adapt.h"
#include "hexadapt/assign/assign.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/generate/generate.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/mesh_check.h"

namespace hexadapt {
namespace {

AdaptOptions guaranteed_options() {
  AdaptOptions o;
  o.method = AdaptMethod::guaranteed;
  return o;
}

template <class M>
void check_guaranteed(const M& grid, const AdaptResult<M>& r, double threshold = 0.3) {
  ASSERT_FALSE(r.stopped_bad_input);
  EXPECT_GE(r.min_quality, threshold);
  EXPECT_EQ(r.n_below_threshold, 0);
  EXPECT_GE(min_quality(r.mesh), threshold);  // independent of the result's own statistics
  const MeshCheckResult check = check_mesh(r.mesh);
  EXPECT_TRUE(check.ok()) << "hanging " << check.hanging_nodes << " inverted "
                          << check.inverted_cells << " nonmanifold " << check.nonmanifold_nodes;
  ASSERT_EQ(r.material.size(), static_cast<std::size_t>(r.mesh.n_cells()));
  for (int m : r.material) EXPECT_TRUE(m >= 0);
  EXPECT_EQ(r.mesh.n_cells(), grid.n_cells() + r.n_cells_added);
  index_t published = 0;
  for (const auto& a : r.cavities) published += a.published;
  EXPECT_EQ(published, r.n_cavities_published);
  for (const auto& s : r.steps) EXPECT_GE(s.min_quality, threshold) << s.name;
  EXPECT_LE(r.dist_final, r.dist_init);
  index_t blocked = 0;
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    EXPECT_EQ(r.blocked[v] != 0, r.has_target[v] && r.distance[v] > 0);
    blocked += r.blocked[v] != 0;
  }
  EXPECT_EQ(blocked, r.n_blocked);
  EXPECT_EQ(r.n_reached + r.n_blocked, [&] {
    index_t n = 0;
    for (char h : r.has_target) n += h != 0;
    return n;
  }());
}

struct GeneratedCase {
  std::string name;
  std::vector<int> dims;
  double time = -1;  // < 0: the case's default
  int extrude = 0;
  double jitter = 0;
};

std::string label(const GeneratedCase& c) {
  std::string s = c.name;
  for (int d : c.dims) s += "_" + std::to_string(d);
  if (c.time >= 0) s += "_t" + std::to_string(static_cast<int>(c.time * 100));
  if (c.extrude) s += "_x" + std::to_string(c.extrude);
  if (c.jitter > 0) s += "_jitter";
  return s;
}

class GeneratedCases : public ::testing::TestWithParam<GeneratedCase> {};

template <class M>
void run_case(const M& grid, const io::MeshData& data) {
  FractionOptions fo;
  const Fractions f = extract_fractions(data, fo);
  const auto a = assign::assign_materials(grid, f);
  const auto r = adapt(grid, f, a.correction.labels, guaranteed_options());
  check_guaranteed(grid, r);
  if (r.dist_init > 0) {
    EXPECT_LT(r.dist_final, r.dist_init);
  }
}

TEST_P(GeneratedCases, KeepTheThresholdAndGetCloser) {
  const GeneratedCase& c = GetParam();
  generate::GenerateOptions o;
  o.case_name = c.name;
  o.dims = c.dims;
  if (c.time >= 0) o.time = c.time;
  o.extrude = c.extrude;
  o.jitter = c.jitter;
  const auto g = generate::generate(o);
  std::visit([&](const auto& grid) { run_case(grid, g.data); }, io::to_mesh(g.data));
}

INSTANTIATE_TEST_SUITE_P(
    Small, GeneratedCases,
    ::testing::Values(GeneratedCase{"triple-point", {28, 12}, 0.5},
                      GeneratedCase{"triple-point", {28, 12}, 1.5},
                      GeneratedCase{"triple-point", {42, 18}, 1.5},
                      GeneratedCase{"stir", {16, 16}, 0.5}, GeneratedCase{"stir", {24, 24}, 1.0},
                      GeneratedCase{"triple-point", {21, 9}, 1.0, 3},
                      GeneratedCase{"vortex", {24, 24}}, GeneratedCase{"venn", {20, 20}},
                      GeneratedCase{"slotted-disk", {24, 24}}, GeneratedCase{"asteroid", {6, 6, 6}},
                      GeneratedCase{"venn", {20, 20}, -1, 0, 0.2}),
    [](const ::testing::TestParamInfo<GeneratedCase>& i) {
      std::string s = label(i.param);
      for (char& ch : s)
        if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return s;
    });

// Where the base method of Fig. 10-a ends below the threshold (adapt_test.cpp), the
// guaranteed one keeps it.
TEST(GuaranteedMethod, HoldsWhereTheBaseMethodInvertsCells) {
  const double h = 1.0 / 6;
  const QuadMesh grid = make_quad_grid(42, 18, Vec3::Zero(), Vec3(h, h, 1));
  const Fractions f = test::sample_fractions(grid, test::triple_point(4.0), 3, 12);
  AdaptOptions base;
  base.method = AdaptMethod::base;
  const auto b = adapt(grid, f, test::majority(f), base);
  EXPECT_LT(b.steps[1].min_quality, 0.0);
  EXPECT_LT(b.min_quality, 0.3);
  const auto r = adapt(grid, f, test::majority(f), guaranteed_options());
  check_guaranteed(grid, r);
  EXPECT_GT(r.dist_init, 0.0);
  EXPECT_LT(r.dist_final, r.dist_init);
  EXPECT_GT(r.n_blocked, 0);  // the price of the guarantee, reported
  EXPECT_FALSE(r.blocking_cells.empty());
}

TEST(GuaranteedMethod, HoldsAHigherThresholdInAnExtrudedCase) {
  const double h = 1.0 / 8;
  const HexMesh grid = make_hex_grid(28, 12, 2, Vec3::Zero(), Vec3(2 * h, 2 * h, h));
  const Fractions f = test::sample_fractions(grid, test::triple_point(7.0), 3, 4);
  AdaptOptions o = guaranteed_options();
  o.threshold = 0.5;
  const auto r = adapt(grid, f, test::majority(f), o);
  check_guaranteed(grid, r, 0.5);
}

TEST(GuaranteedMethod, StopsOnBadInputUnlessAllowed) {
  // A jittered grid whose cells are all near 0.6: a threshold of 0.9 is not met on input.
  const std::vector<Vec3> p = test::jittered_points(10, 10, 0, 0.3, 7);
  const QuadMesh grid = make_quad_grid(10, 10, p);
  const Fractions f = test::sample_fractions(
      grid, [](const Vec3& x) { return x.x() < 4.5; }, 2, 4);
  AdaptOptions o = guaranteed_options();
  o.threshold = 0.9;
  const auto r = adapt(grid, f, test::majority(f), o);
  EXPECT_TRUE(r.stopped_bad_input);
  ASSERT_FALSE(r.bad_input_cells.empty());
  for (CellId c : r.bad_input_cells) EXPECT_LT(grid.cell_quality(c), 0.9);
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) EXPECT_EQ(r.mesh.point(v), grid.point(v));
  o.allow_bad_input = true;
  const auto a = adapt(grid, f, test::majority(f), o);
  EXPECT_FALSE(a.stopped_bad_input);
  // No cell below the threshold gets worse than the input's worst.
  EXPECT_GE(a.min_quality, min_quality(grid) - 1e-12);
}

TEST(GuaranteedMethod, GivesTheSameMeshWhateverTheThreadCount) {
  const QuadMesh grid = make_quad_grid(64, 40);
  const Fractions f = test::sample_fractions(
      grid,
      [](const Vec3& p) {
        return static_cast<int>(std::floor((p.x() + 2.0 * std::sin(0.3 * p.y())) / 4.1)) % 3;
      },
      3, 4);
  set_threads(1);
  const auto a = adapt(grid, f, test::majority(f), guaranteed_options());
  set_threads(2);
  const auto b = adapt(grid, f, test::majority(f), guaranteed_options());
  set_threads(0);
  ASSERT_EQ(a.mesh.n_nodes(), b.mesh.n_nodes());
  for (NodeId v : id_range<NodeId>(a.mesh.n_nodes())) ASSERT_EQ(a.mesh.point(v), b.mesh.point(v));
  EXPECT_EQ(a.blocked.raw(), b.blocked.raw());
  EXPECT_EQ(a.dist_final, b.dist_final);
}

TEST(GuaranteedMethod, RejectsBadOptions) {
  const QuadMesh grid = make_quad_grid(4, 4);
  const Fractions f = test::sample_fractions(
      grid, [](const Vec3& p) { return p.x() < 1.5; }, 2, 4);
  AdaptOptions o = guaranteed_options();
  o.max_loops = -1;
  EXPECT_THROW(adapt(grid, f, test::majority(f), o), OptionError);
  o.max_loops = 3;
  o.loop_tolerance = -1;
  EXPECT_THROW(adapt(grid, f, test::majority(f), o), OptionError);
}

}  // namespace
}  // namespace hexadapt
