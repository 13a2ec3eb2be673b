#include "hexadapt/assign/enumerate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "assign_test_cases.h"
#include "brute_force_manifold.h"
#include "hexadapt/assign/cost.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::assign {
namespace {

using test::random_fractions;

/// Every assignment of the ball's cells over the candidates, in the test's own loop, sorted
/// by cost; the `keep` cheapest that the independent checker finds manifold, their costs.
template <class M>
std::vector<double> exhaustive_costs(const M& mesh, NodeId n, const Fractions& f,
                                     const IdVector<CellId, double>& vol,
                                     const std::vector<int>& materials, int keep) {
  const auto around = mesh.node_cells(n);
  const std::size_t k = around.size(), p = materials.size();
  std::vector<std::pair<double, std::vector<int>>> all;
  std::vector<std::size_t> digit(k, 0);
  while (true) {
    double cost = 0;
    std::vector<int> config(k);
    for (std::size_t i = 0; i < k; ++i) {
      config[i] = materials[digit[i]];
      cost += (1 - f(around[i], config[i])) * vol[around[i]];
    }
    all.emplace_back(cost, config);
    std::size_t i = 0;
    while (i < k && ++digit[i] == p) digit[i++] = 0;
    if (i == k) break;
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<double> costs;
  CellMaterials labels(static_cast<std::size_t>(mesh.n_cells()), -1);
  for (const auto& [cost, config] : all) {
    for (std::size_t i = 0; i < k; ++i) labels[around[i]] = config[i];
    bool ok = true;
    for (int m : materials) ok = ok && test::link_manifold(mesh, n, labels, m);
    if (ok) costs.push_back(cost);
    if (static_cast<int>(costs.size()) == keep) break;
  }
  return costs;
}

template <class M>
void check_single_node(const M& mesh, NodeId n, const Fractions& f, int keep, int max_materials) {
  const auto vol = cell_volumes(mesh);
  const LocalBall<M> ball(mesh, n);
  const LocalProblem problem = local_problem(ball, f, vol, max_materials);
  ConfigurationStore store(keep);
  const auto stats = enumerate_configurations(ball, problem, 100'000'000, store);
  EXPECT_FALSE(stats.truncated);
  const auto costs = exhaustive_costs(mesh, n, f, vol, problem.materials, keep);
  ASSERT_EQ(store.size(), std::min<int>(keep, static_cast<int>(costs.size())));
  for (int i = 0; i < store.size(); ++i) {
    EXPECT_NEAR(store[i].cost, costs[static_cast<std::size_t>(i)], 1e-12) << "rank " << i;
    CellMaterials labels(static_cast<std::size_t>(mesh.n_cells()), -1);
    for (int c = 0; c < ball.n_cells(); ++c)
      labels[ball.cell(c)] = store[i].labels[static_cast<std::size_t>(c)];
    for (int m : problem.materials) EXPECT_TRUE(test::link_manifold(mesh, n, labels, m));
  }
  // branch and bound examined fewer complete configurations than there are
  double all = 1;
  for (int i = 0; i < ball.n_cells(); ++i) all *= static_cast<double>(problem.materials.size());
  if (all > 1000) {
    EXPECT_LT(static_cast<double>(stats.leaves), all);
  }
}

TEST(Enumerate, HexCentreNodeIsTheExhaustiveOptimum) {
  const HexMesh mesh = make_hex_grid(2, 2, 2);
  for (unsigned seed = 1; seed <= 6; ++seed)
    check_single_node(mesh, NodeId(13), random_fractions(8, 3, 2, seed), 20, 5);
}

TEST(Enumerate, QuadNodesAreTheExhaustiveOptimum) {
  const QuadMesh mesh = make_quad_grid(2, 2);
  for (unsigned seed = 1; seed <= 10; ++seed)
    for (NodeId n : {NodeId(4), NodeId(1)})  // interior and on the boundary
      check_single_node(mesh, n, random_fractions(4, 4, 3, seed), 5, 5);
}

TEST(Enumerate, FourAndFiveMaterialsAtANode) {
  const HexMesh mesh = make_hex_grid(2, 2, 2);
  check_single_node(mesh, NodeId(13), random_fractions(8, 4, 4, 11), 20, 5);
  check_single_node(mesh, NodeId(13), random_fractions(8, 5, 3, 12), 20, 5);
  const QuadMesh quads = make_quad_grid(2, 2);
  check_single_node(quads, NodeId(4), random_fractions(4, 5, 5, 13), 50, 5);
}

TEST(Enumerate, JitteredHexBallUsesEachCellsOwnVolume) {
  std::vector<Vec3> pts;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        pts.emplace_back(i + jitter(rng), j + jitter(rng), k + jitter(rng));
  const HexMesh mesh = make_hex_grid(2, 2, 2, pts);
  check_single_node(mesh, NodeId(13), random_fractions(8, 3, 3, 21), 20, 5);
}

TEST(Enumerate, CandidatesAreTheMostPresentMaterials) {
  const QuadMesh mesh = make_quad_grid(2, 2);
  Fractions f(4, {"a", "b", "c", "d"});
  f(CellId(0), 0) = 1;
  f(CellId(1), 1) = 0.9;
  f(CellId(1), 3) = 0.1;
  f(CellId(2), 2) = 1;
  f(CellId(3), 1) = 1;
  const LocalBall<QuadMesh> ball(mesh, NodeId(4));
  const auto p = local_problem(ball, f, cell_volumes(mesh), 3);
  EXPECT_EQ(p.materials, (std::vector<int>{0, 1, 2}));  // d holds the least volume
  EXPECT_EQ(local_problem(ball, f, cell_volumes(mesh), 5).materials,
            (std::vector<int>{0, 1, 2, 3}));
}

TEST(ConfigurationStore, KeepsTheBestInOrderAndHandsThemOutOnce) {
  ConfigurationStore s(3);
  s.offer(5, {5});
  s.offer(1, {1});
  s.offer(3, {3});
  s.offer(3, {33});  // equal cost: after the first arrival
  s.offer(9, {9});
  ASSERT_EQ(s.size(), 3);
  EXPECT_EQ(s[0].labels, std::vector<int>{1});
  EXPECT_EQ(s[1].labels, std::vector<int>{3});
  EXPECT_EQ(s[2].labels, std::vector<int>{33});
  EXPECT_EQ(s.take_next()->labels, std::vector<int>{1});
  EXPECT_EQ(s.take_next()->labels, std::vector<int>{3});
  EXPECT_EQ(s.take_next()->labels, std::vector<int>{33});
  EXPECT_EQ(s.take_next(), nullptr);
  EXPECT_THROW(ConfigurationStore{0}, OptionError);
}

}  // namespace
}  // namespace hexadapt::assign
