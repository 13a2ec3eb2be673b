// The assignment spread over the ranks of an MPI job (run under mpirun -np N): every rank
// assigns its slab of a grid, and the owned labels gathered in rank order, the statistics and
// the failure must be those of one rank assigning the whole grid.
#include <gtest/gtest.h>

#include <algorithm>

#include "../../assign/assign_test_cases.h"
#include "hexadapt/assign/assign.h"
#include "hexadapt/dist/mpi_communicator.h"
#include "slab_case.h"

namespace hexadapt {
namespace {

// Buffers of different sizes, an empty one on rank 0, come back whole and in order, on every
// rank or on the root only.
TEST(MpiCommunicator, GathersInRoundsKeepEachRanksBytesInOrder) {
  const auto bytes_of = [](int rank) {
    std::vector<std::uint8_t> b(static_cast<std::size_t>(rank * 1237));
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(rank * 7 + i);
    return b;
  };
  const auto mine = bytes_of(test::world().rank());
  const auto all = test::world().all_gather(mine);
  ASSERT_EQ(all.size(), static_cast<std::size_t>(test::world().size()));
  for (int r = 0; r < test::world().size(); ++r)
    EXPECT_EQ(all[static_cast<std::size_t>(r)], bytes_of(r));
  const int root = test::world().size() - 1;
  const auto at_root = test::world().gather(mine, root);
  if (test::world().rank() == root) {
    ASSERT_EQ(at_root.size(), static_cast<std::size_t>(test::world().size()));
    for (int r = 0; r < test::world().size(); ++r)
      EXPECT_EQ(at_root[static_cast<std::size_t>(r)], bytes_of(r));
  } else {
    EXPECT_TRUE(at_root.empty());
  }
}

// Each rank exchanges with the ranks next to it, in an order of peers that differs between
// ranks: messages of several rounds (over 1000 bytes), an empty one, each from the right rank.
TEST(MpiCommunicator, ExchangesWithPeersInAnyOrder) {
  const int me = test::world().rank(), n = test::world().size();
  const auto bytes_from_to = [](int from, int to) {
    std::vector<std::uint8_t> b(from == 0 ? 0 : static_cast<std::size_t>(700 * from + 31 * to));
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(from * 13 + to + i);
    return b;
  };
  std::vector<int> peers;
  for (int r : {me + 1, me - 1})
    if (r >= 0 && r < n) peers.push_back(r);
  if (me % 2 == 1) std::reverse(peers.begin(), peers.end());
  std::vector<std::vector<std::uint8_t>> to;
  for (int r : peers) to.push_back(bytes_from_to(me, r));
  const auto got = test::world().exchange(peers, to);
  ASSERT_EQ(got.size(), peers.size());
  for (std::size_t i = 0; i < peers.size(); ++i) EXPECT_EQ(got[i], bytes_from_to(peers[i], me));
  EXPECT_THROW(dist::serial().exchange({1}, {{}}), InternalError);
}

template <class M>
void expect_same_as_one_rank(const M& whole, const Fractions& fractions,
                             const std::array<int, 3>& cells,
                             const assign::AssignOptions& options) {
  const assign::AssignResult one = assign::assign_materials(whole, fractions, options);
  const dist::Slab slab =
      dist::structured_slab(cells, M::dim, test::world().rank(), test::world().size(), 2);
  const auto [mesh, part] = test::held_part(whole, fractions, cells, slab);
  const dist::Distribution where{test::world(), slab.block};
  const assign::AssignResult r = assign::assign_materials(mesh, part, options, where);

  std::vector<int> owned;
  for (index_t c = slab.block.owned_cell_first; c < slab.block.owned_cell_end; ++c)
    owned.push_back(r.correction.labels[CellId(c)]);
  const std::vector<int> gathered = dist::all_gather_values(test::world(), owned);
  ASSERT_EQ(gathered.size(), static_cast<std::size_t>(whole.n_cells()));
  index_t differ = 0;
  for (CellId c : id_range<CellId>(whole.n_cells()))
    differ += gathered[c.idx()] != one.correction.labels[c] ? 1 : 0;
  EXPECT_EQ(differ, 0) << "cells assigned otherwise than on one rank";

  const assign::CorrectionResult &a = r.correction, &b = one.correction;
  EXPECT_EQ(a.solved, b.solved);
  EXPECT_EQ(a.non_manifold_initial, b.non_manifold_initial);
  EXPECT_EQ(a.rounds, b.rounds);
  EXPECT_EQ(a.node_solves, b.node_solves);
  EXPECT_EQ(a.nodes_treated, b.nodes_treated);
  EXPECT_EQ(a.max_visits, b.max_visits);
  EXPECT_EQ(a.cells_changed, b.cells_changed);
  EXPECT_EQ(a.leaves, b.leaves);
  EXPECT_EQ(a.truncated_enumerations, b.truncated_enumerations);
  EXPECT_EQ(a.cost_initial, b.cost_initial);  // exact sums: the same bits
  EXPECT_EQ(a.cost_final, b.cost_final);
  ASSERT_EQ(a.failure.has_value(), b.failure.has_value());
  if (a.failure) {
    EXPECT_EQ(a.failure->node, b.failure->node);
    EXPECT_EQ(a.failure->position, b.failure->position);
    EXPECT_EQ(a.failure->materials, b.failure->materials);
    EXPECT_EQ(a.failure->stored, b.failure->stored);
  }
  ASSERT_EQ(r.balance.size(), one.balance.size());
  for (std::size_t m = 0; m < r.balance.size(); ++m) {
    EXPECT_EQ(r.balance[m].assigned_cells, one.balance[m].assigned_cells);
    EXPECT_EQ(r.balance[m].input_volume, one.balance[m].input_volume);
    EXPECT_EQ(r.balance[m].assigned_volume, one.balance[m].assigned_volume);
    EXPECT_EQ(r.balance[m].input_share, one.balance[m].input_share);
  }
}

TEST(AssignOnRanks, NoisyHexFractionsAsOnOneRank) {
  const std::array<int, 3> cells{9, 8, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 3);
  const Fractions f = test::random_fractions(mesh.n_cells(), 3, 3, 11);
  const assign::AssignResult one = assign::assign_materials(mesh, f);
  ASSERT_GT(one.correction.non_manifold_initial, 50);  // many nodes, many rounds
  ASSERT_GT(one.correction.rounds, 3);
  expect_same_as_one_rank(mesh, f, cells, {});
}

TEST(AssignOnRanks, BallsInAHexGridAsOnOneRank) {
  const std::array<int, 3> cells{14, 13, 15};
  const HexMesh mesh = make_hex_grid(cells[0], cells[1], cells[2]);
  const Fractions f = test::ball_fractions(
      mesh, {{Vec3(5.3, 6.1, 6.7), 4.2}, {Vec3(9.1, 6.4, 8.2), 3.3}, {Vec3(7.0, 7.0, 1.5), 3.0}});
  expect_same_as_one_rank(mesh, f, cells, {});
}

TEST(AssignOnRanks, NoisyQuadFractionsAsOnOneRank) {
  const std::array<int, 3> cells{23, 17, 1};
  const auto mesh = test::jittered_grid<QuadMesh>(cells, 5);
  const Fractions f = test::random_fractions(mesh.n_cells(), 4, 3, 2);
  expect_same_as_one_rank(mesh, f, cells, {});
}

// A material that is nowhere the majority (at most 0.3 of a cell), kept: its cells are
// chosen among every rank's, as on one rank.
TEST(AssignOnRanks, KeptMaterialsAsOnOneRank) {
  const std::array<int, 3> cells{9, 8, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 6);
  Fractions f = test::random_fractions(mesh.n_cells(), 3, 3, 8);
  for (CellId c : id_range<CellId>(f.n_cells())) {
    f(c, 0) += 0.7 * f(c, 2);
    f(c, 2) *= 0.3;
  }
  assign::AssignOptions options;
  options.keep_materials = true;
  const assign::AssignResult one = assign::assign_materials(mesh, f, options);
  ASSERT_EQ(one.kept.size(), 1u);
  ASSERT_GT(one.kept[0].cells, 20);
  expect_same_as_one_rank(mesh, f, cells, options);
  const dist::Slab slab =
      dist::structured_slab(cells, 3, test::world().rank(), test::world().size(), 2);
  const auto [part_mesh, part] = test::held_part(mesh, f, cells, slab);
  const assign::AssignResult r =
      assign::assign_materials(part_mesh, part, options, {test::world(), slab.block});
  ASSERT_EQ(r.kept.size(), 1u);
  EXPECT_EQ(r.kept[0].material, one.kept[0].material);
  EXPECT_EQ(r.kept[0].cells, one.kept[0].cells);
}

TEST(AssignOnRanks, AFailureIsTheOneOfOneRank) {
  const std::array<int, 3> cells{9, 8, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 4);
  const Fractions f = test::random_fractions(mesh.n_cells(), 4, 4, 5);
  assign::AssignOptions options;
  options.correction.keep = 1;
  options.correction.spare_neighbours = false;
  ASSERT_TRUE(assign::assign_materials(mesh, f, options).correction.failure.has_value());
  expect_same_as_one_rank(mesh, f, cells, options);
}

// Small pieces (min_island) that cross the ranks' borders: the pieces are joined over the
// ranks, and the cells reassigned, the figures and what follows are those of one rank.
TEST(AssignOnRanks, SmallPiecesAsOnOneRank) {
  const std::array<int, 3> cells{9, 8, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 9);
  const Fractions f = test::random_fractions(mesh.n_cells(), 3, 2, 21);
  assign::AssignOptions options;
  options.min_island = 6;
  const assign::AssignResult one = assign::assign_materials(mesh, f, options);
  ASSERT_GT(one.islands.islands, 20);
  expect_same_as_one_rank(mesh, f, cells, options);
  const dist::Slab slab =
      dist::structured_slab(cells, 3, test::world().rank(), test::world().size(), 2);
  const auto [part_mesh, part] = test::held_part(mesh, f, cells, slab);
  const assign::AssignResult r =
      assign::assign_materials(part_mesh, part, options, {test::world(), slab.block});
  EXPECT_EQ(r.islands.islands, one.islands.islands);
  EXPECT_EQ(r.islands.cells, one.islands.cells);
  EXPECT_EQ(r.islands.left, one.islands.left);
  EXPECT_EQ(r.small_pieces_final, one.small_pieces_final);
}

}  // namespace
}  // namespace hexadapt

int main(int argc, char** argv) {
  hexadapt::dist::MpiSession session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
