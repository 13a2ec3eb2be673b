// The dual graph on one rank (dist/dual_graph.h): a structured grid's cells are neighbours
// exactly when they differ by one step along one axis; a face shared by three cells pairs
// all three; cells sharing an edge only are not neighbours.
#include "hexadapt/dist/dual_graph.h"

#include <gtest/gtest.h>

#include "hexadapt/mesh/structured.h"

namespace hexadapt::dist {
namespace {

std::vector<std::int64_t> global(const std::vector<NodeId>& cells) {
  std::vector<std::int64_t> out;
  for (const NodeId n : cells) out.push_back(n.value());
  return out;
}

std::vector<std::int64_t> neighbours_of(const DistGraph& g, std::int64_t v) {
  const auto at = [&](std::int64_t i) { return g.offsets[static_cast<std::size_t>(i)]; };
  return {g.neighbours.begin() + at(v), g.neighbours.begin() + at(v + 1)};
}

TEST(DualGraph, AGridsCellsNeighbourAcrossFaces) {
  constexpr int nx = 3, ny = 2, nz = 2;
  std::vector<NodeId> cells;
  append_structured_cells(nx, ny, nz, cells);
  const DistGraph g = dual_graph(serial(), 8, global(cells));
  ASSERT_EQ(g.n_vertices(), nx * ny * nz);
  EXPECT_EQ(g.first, 0);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        std::vector<std::int64_t> expected;
        const auto add = [&](int a, int b, int c) {
          if (a >= 0 && a < nx && b >= 0 && b < ny && c >= 0 && c < nz)
            expected.push_back(a + nx * (b + ny * c));
        };
        add(i, j, k - 1), add(i, j - 1, k), add(i - 1, j, k);
        add(i + 1, j, k), add(i, j + 1, k), add(i, j, k + 1);
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(neighbours_of(g, i + nx * (j + ny * k)), expected) << i << " " << j << " " << k;
      }
}

TEST(DualGraph, QuadsNeighbourAcrossEdgesAndAFaceOfThreeCellsPairsThemAll) {
  // Quads 0 and 1 side by side; quad 2 repeats edge 1-2 of quad 0 (three cells on it) and
  // quad 3 touches quad 0 at node 0 only.
  const std::vector<std::int64_t> quads = {0, 1, 2, 3, 1, 4, 5, 2, 1, 6, 7, 2, 0, 8, 9, 10};
  const DistGraph g = dual_graph(serial(), 4, quads);
  EXPECT_EQ(neighbours_of(g, 0), (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(neighbours_of(g, 1), (std::vector<std::int64_t>{0, 2}));
  EXPECT_EQ(neighbours_of(g, 2), (std::vector<std::int64_t>{0, 1}));
  EXPECT_TRUE(neighbours_of(g, 3).empty());
}

}  // namespace
}  // namespace hexadapt::dist
