#include "hexadapt/dist/block.h"

#include <gtest/gtest.h>

#include "hexadapt/assign/correction.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {
namespace {

TEST(StructuredSlab, OwnedLayersTileTheGridAndGhostsStopAtItsEnds) {
  const std::array<int, 3> cells{3, 2, 10};
  std::int64_t next_cell = 0, next_node = 0;
  for (int r = 0; r < 4; ++r) {
    const Slab s = structured_slab(cells, 3, r, 4, 2);
    const Block& b = s.block;
    EXPECT_EQ(b.global(CellId(b.owned_cell_first)), next_cell) << "rank " << r;
    EXPECT_EQ(b.global(NodeId(b.owned_node_first)), next_node) << "rank " << r;
    next_cell = b.global(CellId(b.owned_cell_end - 1)) + 1;
    next_node = b.global(NodeId(b.owned_node_end - 1)) + 1;
    EXPECT_EQ(b.held_cells, 6 * s.held[2]);
    EXPECT_EQ(b.held_nodes, 12 * (s.held[2] + 1));
    EXPECT_EQ(s.first_layer, b.cell_offset / 6);
    // two ghost layers on each side, fewer at the ends
    EXPECT_EQ(b.owned_cell_first, r == 0 ? 0 : 12);
    EXPECT_EQ(b.held_cells - b.owned_cell_end, r == 3 ? 0 : 12);
    EXPECT_FALSE(b.local_cell(b.cell_offset - 1).valid());
    EXPECT_EQ(b.local_cell(b.cell_offset + 5), CellId(5));
  }
  EXPECT_EQ(next_cell, 60);   // every cell owned once
  EXPECT_EQ(next_node, 132);  // and every node, the last layer by the last rank
}

TEST(StructuredSlab, TwoDimensionsCutAcrossY) {
  const Slab s = structured_slab({5, 4, 1}, 2, 1, 2, 1);
  EXPECT_EQ(s.held[0], 5);
  EXPECT_EQ(s.held[1], 3);  // owned rows 2, 3 and one ghost row below
  EXPECT_EQ(s.block.cell_offset, 5);
  EXPECT_EQ(s.block.node_offset, 6);
  EXPECT_EQ(s.block.owned_node_end, 6 * 4);  // the last rank owns the top row of nodes
}

TEST(StructuredSlab, MoreRanksThanLayersAreRefused) {
  EXPECT_THROW(structured_slab({4, 4, 3}, 3, 0, 4, 1), OptionError);
  EXPECT_THROW(structured_slab({0, 4, 3}, 3, 0, 1, 1), OptionError);
}

TEST(DistBuffer, ValuesComeBackInOrderAndAShortMessageIsABug) {
  Buffer b;
  b.put(std::int64_t{-7});
  b.put_vector(std::vector<double>{1.5, 2.5});
  b.put(true);
  Buffer r(b.bytes());
  EXPECT_EQ(r.get<std::int64_t>(), -7);
  EXPECT_EQ(r.get_vector<double>(), (std::vector<double>{1.5, 2.5}));
  EXPECT_TRUE(r.get<bool>());
  EXPECT_TRUE(r.done());
  EXPECT_THROW(r.get<int>(), InternalError);
}

TEST(DistBuffer, OneRankGathersItsOwnValues) {
  EXPECT_EQ(all_gather_values(serial(), std::vector<int>{3, 1, 2}), (std::vector<int>{3, 1, 2}));
  EXPECT_EQ(sum_in_rank_order(serial(), 2.5), 2.5);
}

}  // namespace
}  // namespace hexadapt::dist
