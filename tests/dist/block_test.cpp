#include "hexadapt/dist/block.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// The layers each rank owns in a cut of `weights` over `size` ranks.
std::vector<std::array<int, 2>> owned_layers(const std::array<int, 3>& cells, int size,
                                             const std::vector<double>& weights) {
  std::vector<std::array<int, 2>> out;
  for (int r = 0; r < size; ++r)
    out.push_back(weighted_slab(cells, 3, r, size, 1, weights).owned_layers);
  return out;
}

using Layers = std::vector<std::array<int, 2>>;

TEST(WeightedSlab, EqualWeightsGiveEveryRankAtMostItsShareOfLayers) {
  const std::array<int, 3> cells{3, 2, 10};
  for (int size = 1; size <= 10; ++size) {
    const Layers cut = owned_layers(cells, size, std::vector<double>(10, 2.5));
    int next = 0;
    for (const auto& [first, end] : cut) {
      EXPECT_EQ(first, next) << size << " ranks";
      EXPECT_GE(end - first, 1) << size << " ranks";
      EXPECT_LE(end - first, (10 + size - 1) / size) << size << " ranks";
      next = end;
    }
    EXPECT_EQ(next, 10);
  }
}

TEST(WeightedSlab, TheHeaviestRankIsAsLightAsACutAllows) {
  const std::array<int, 3> cells{2, 2, 8};
  // Most of the weight in layer 5: it goes to the second rank (14 against 17 the other way).
  EXPECT_EQ(owned_layers(cells, 2, {1, 1, 1, 1, 1, 12, 1, 1}), (Layers{{0, 5}, {5, 8}}));
  EXPECT_EQ(owned_layers(cells, 2, {1, 1, 1, 1, 1, 9, 1, 1}), (Layers{{0, 5}, {5, 8}}));
  EXPECT_EQ(owned_layers(cells, 2, {1, 1, 1, 1, 1, 1, 1, 7}), (Layers{{0, 7}, {7, 8}}));
  // A belt in the middle: the middle ranks own one layer each, the ends three.
  EXPECT_EQ(owned_layers(cells, 4, {1, 1, 1, 10, 10, 1, 1, 1}),
            (Layers{{0, 3}, {3, 4}, {4, 5}, {5, 8}}));
  // Everything in layer 0: every rank still owns a layer, the first takes the rest it can.
  EXPECT_EQ(owned_layers(cells, 3, {5, 0, 0, 0, 0, 0, 0, 0}), (Layers{{0, 6}, {6, 7}, {7, 8}}));
  // All weights zero: as equal weights.
  EXPECT_EQ(owned_layers(cells, 2, std::vector<double>(8, 0.0)), (Layers{{0, 4}, {4, 8}}));
  // The slab holds its ghost layers around the owned ones.
  const Slab s = weighted_slab(cells, 3, 2, 4, 1, {1, 1, 1, 10, 10, 1, 1, 1});
  EXPECT_EQ(s.first_layer, 3);
  EXPECT_EQ(s.held[2], 3);
  EXPECT_EQ(s.block.owned_cell_first, 4);
  EXPECT_EQ(s.block.owned_cell_end, 8);
}

TEST(WeightedSlab, BadWeightsAreRefused) {
  const std::array<int, 3> cells{2, 2, 3};
  EXPECT_THROW(weighted_slab(cells, 3, 0, 2, 1, {1, -1, 1}), OptionError);
  EXPECT_THROW(weighted_slab(cells, 3, 0, 2, 1, {1, std::nan(""), 1}), OptionError);
  EXPECT_THROW(weighted_slab(cells, 3, 0, 2, 1, {1, 1}), InternalError);
  EXPECT_THROW(weighted_slab(cells, 3, 0, 4, 1, {1, 1, 1}), OptionError);
}

TEST(LayerSums, OneRankSumsEachLayerOfItsCells) {
  const Slab s = structured_slab({2, 1, 3}, 3, 0, 1, 1);
  EXPECT_EQ(layer_sums(serial(), s, {1, 2, 3, 4, 5, 6}), (std::vector<double>{3, 7, 11}));
  EXPECT_THROW(layer_sums(serial(), s, {1, 2}), InternalError);
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
