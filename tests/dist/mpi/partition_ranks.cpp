// An unstructured mesh cut over the ranks of an MPI job (run under mpirun -np N): the dual
// graph built on the ranks is the one-process graph, PT-Scotch's parts are the same run
// after run, balanced and cut along few faces, and the cells moved to their parts keep
// every id, node and array.
#include <gtest/gtest.h>

#include "hexadapt/dist/dual_graph.h"
#include "hexadapt/dist/scotch_partition.h"
#include "hexadapt/io/mesh_part.h"
#include "hexadapt/mesh/structured.h"
#include "slab_case.h"

namespace hexadapt {
namespace {

constexpr int side = 12;  // cells per axis

std::vector<std::int64_t> grid_cells() {
  std::vector<NodeId> cells;
  append_structured_cells(side, side, side, cells);
  std::vector<std::int64_t> out;
  for (const NodeId c : cells) out.push_back(c.value());
  return out;
}

// Grid node g's point (i, j, k), and the point array's value there.
Vec3 grid_point(std::int64_t g) {
  return {static_cast<double>(g % (side + 1)), static_cast<double>(g / (side + 1) % (side + 1)),
          static_cast<double>(g / ((side + 1) * (side + 1)))};
}

double point_sum(const Vec3& p) {
  return p[0] + 10 * p[1] + 100 * p[2];
}

// This rank's share of the grid's cells (a contiguous range, every rank's in rank order,
// the first ranks one more), with the nodes they use and arrays of known values.
io::MeshPart grid_part() {
  const int rank = test::world().rank(), size = test::world().size();
  const std::int64_t total = side * side * side;
  const std::int64_t first = total * rank / size, end = total * (rank + 1) / size;
  const std::vector<std::int64_t> all = grid_cells();
  io::MeshPart part;
  part.n_cells = total;
  part.n_nodes = (side + 1) * (side + 1) * (side + 1);
  io::MeshData& d = part.data;
  d.dim = 3;
  std::vector<std::int64_t> used(all.begin() + first * 8, all.begin() + end * 8);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  part.node_ids = used;
  io::DataArray id{"id", 1, io::ScalarType::int64, {}}, sum{"sum", 1, io::ScalarType::float64, {}};
  for (const std::int64_t g : used) {
    d.points.push_back(grid_point(g));
    sum.values.push_back(point_sum(d.points.back()));
  }
  for (std::int64_t c = first; c < end; ++c) {
    part.cell_ids.push_back(c);
    id.values.push_back(static_cast<double>(c));
    for (int v = 0; v < 8; ++v) {
      const auto it =
          std::lower_bound(used.begin(), used.end(), all[static_cast<std::size_t>(c * 8 + v)]);
      d.cells.push_back(NodeId(static_cast<index_t>(it - used.begin())));
    }
  }
  d.cell_data = {id};
  d.point_data = {sum};
  return part;
}

std::vector<std::int64_t> cell_nodes(const io::MeshPart& part) {
  std::vector<std::int64_t> out;
  for (const NodeId v : part.data.cells) out.push_back(part.node_ids[v.idx()]);
  return out;
}

TEST(PartitionOnRanks, TheDualGraphIsTheOneProcessGraph) {
  const dist::DistGraph one = dist::dual_graph(dist::serial(), 8, grid_cells());
  const dist::DistGraph g = dist::dual_graph(test::world(), 8, cell_nodes(grid_part()));
  const std::vector<std::int64_t> firsts =
      dist::all_gather_values(test::world(), std::vector<std::int64_t>{g.first});
  EXPECT_EQ(g.first, side * side * side * test::world().rank() / test::world().size());
  const std::int64_t base = g.offsets.front();
  for (std::int64_t v = 0; v < g.n_vertices(); ++v) {
    const auto at = [](const dist::DistGraph& h, std::int64_t i) {
      return h.offsets[static_cast<std::size_t>(i)];
    };
    const std::vector<std::int64_t> mine(g.neighbours.begin() + at(g, v) - base,
                                         g.neighbours.begin() + at(g, v + 1) - base);
    const std::vector<std::int64_t> whole(one.neighbours.begin() + at(one, g.first + v),
                                          one.neighbours.begin() + at(one, g.first + v + 1));
    EXPECT_EQ(mine, whole) << "cell " << g.first + v;
  }
}

// The faces between cells of different parts, over all ranks.
std::int64_t cut_faces(const dist::DistGraph& g, const std::vector<int>& part) {
  const std::vector<int> all = dist::all_gather_values(test::world(), part);
  std::int64_t cut = 0;
  for (std::int64_t v = 0; v < g.n_vertices(); ++v)
    for (std::int64_t e = g.offsets[static_cast<std::size_t>(v)];
         e < g.offsets[static_cast<std::size_t>(v + 1)]; ++e)
      cut += all[static_cast<std::size_t>(g.first + v)] !=
             all[static_cast<std::size_t>(g.neighbours[static_cast<std::size_t>(e)])];
  return dist::sum_in_rank_order(test::world(), cut) / 2;
}

TEST(PartitionOnRanks, ScotchPartsAreReproducibleBalancedAndCutFewFaces) {
  const auto& comm = dynamic_cast<const dist::MpiCommunicator&>(test::world());
  const int size = comm.size();
  const dist::DistGraph g = dist::dual_graph(comm, 8, cell_nodes(grid_part()));
  const std::vector<int> part = dist::scotch_partition(comm, g, size);
  EXPECT_EQ(dist::scotch_partition(comm, g, size), part);
  std::vector<std::int64_t> count(static_cast<std::size_t>(size), 0);
  for (const int p : part) {
    ASSERT_GE(p, 0);
    ASSERT_LT(p, size);
    ++count[static_cast<std::size_t>(p)];
  }
  std::vector<std::int64_t> total(static_cast<std::size_t>(size), 0);
  const std::vector<std::int64_t> all = dist::all_gather_values(comm, count);
  for (std::size_t i = 0; i < all.size(); ++i) total[i % static_cast<std::size_t>(size)] += all[i];
  const double share = static_cast<double>(side * side * side) / size;
  for (const std::int64_t t : total) {
    EXPECT_GT(t, 0);
    EXPECT_LE(static_cast<double>(t), 1.05 * share + 1);
  }
  // Slabs across one axis cut (size - 1) n^2 faces; Scotch's parts may not be slabs but must
  // not cut much more.
  const std::int64_t cut = cut_faces(g, part);
  EXPECT_EQ(cut > 0, size > 1);
  EXPECT_LE(cut, 13 * (size - 1) * side * side / 10) << cut;
}

TEST(PartitionOnRanks, MovedCellsKeepTheirIdsNodesAndArrays) {
  const auto& comm = dynamic_cast<const dist::MpiCommunicator&>(test::world());
  const io::MeshPart part = grid_part();
  const std::vector<int> to =
      dist::scotch_partition(comm, dist::dual_graph(comm, 8, cell_nodes(part)), comm.size());
  const io::MeshPart moved = io::migrate(comm, part, to);
  EXPECT_EQ(moved.n_cells, part.n_cells);
  EXPECT_TRUE(std::is_sorted(moved.cell_ids.begin(), moved.cell_ids.end()));
  EXPECT_TRUE(std::is_sorted(moved.node_ids.begin(), moved.node_ids.end()));
  // The cells here are exactly those of this rank's part.
  const std::vector<int> parts = dist::all_gather_values(comm, to);
  std::vector<std::int64_t> expected;
  for (std::size_t c = 0; c < parts.size(); ++c)
    if (parts[c] == comm.rank()) expected.push_back(static_cast<std::int64_t>(c));
  EXPECT_EQ(moved.cell_ids, expected);
  // Every cell has its id array, its grid nodes, their points and point array.
  const std::vector<std::int64_t> grid = grid_cells();
  const io::MeshData& d = moved.data;
  for (std::size_t c = 0; c < moved.cell_ids.size(); ++c) {
    const std::int64_t g = moved.cell_ids[c];
    EXPECT_EQ(d.cell_data[0].values[c], static_cast<double>(g));
    for (std::size_t v = 0; v < 8; ++v) {
      const std::size_t local = d.cells[c * 8 + v].idx();
      const std::int64_t node = grid[static_cast<std::size_t>(g) * 8 + v];
      ASSERT_EQ(moved.node_ids[local], node);
      EXPECT_EQ(d.points[local], grid_point(node));
      EXPECT_EQ(d.point_data[0].values[local], point_sum(grid_point(node)));
    }
  }
  // No node is held that no cell uses.
  std::vector<char> used(moved.node_ids.size(), 0);
  for (const NodeId v : d.cells) used[v.idx()] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
}

TEST(PartitionOnRanks, AGhostLayerHoldsEveryCellAroundTheOwnedNodes) {
  const auto& comm = dynamic_cast<const dist::MpiCommunicator&>(test::world());
  const io::MeshPart part = grid_part();
  const std::vector<int> to =
      dist::scotch_partition(comm, dist::dual_graph(comm, 8, cell_nodes(part)), comm.size());
  const io::MeshPart owned = io::migrate(comm, part, to);
  const io::GhostedPart g = io::with_ghost_layers(comm, owned);
  const std::size_t n_owned = owned.cell_ids.size();
  ASSERT_EQ(g.owned_cells, static_cast<index_t>(n_owned));
  EXPECT_EQ(
      std::vector<std::int64_t>(g.part.cell_ids.begin(),
                                g.part.cell_ids.begin() + static_cast<std::ptrdiff_t>(n_owned)),
      owned.cell_ids);
  // From the whole grid: the ghosts are the other ranks' cells using a node of this rank's
  // cells, and a node's owner is the lowest rank whose cells use it.
  const std::vector<int> parts = dist::all_gather_values(comm, to);
  const std::vector<std::int64_t> grid = grid_cells();
  const std::size_t n_nodes = (side + 1) * (side + 1) * (side + 1);
  std::vector<int> lowest(n_nodes, comm.size());
  std::vector<char> mine(n_nodes, 0);
  for (std::size_t c = 0; c < parts.size(); ++c)
    for (std::size_t v = 0; v < 8; ++v) {
      const auto node = static_cast<std::size_t>(grid[c * 8 + v]);
      lowest[node] = std::min(lowest[node], parts[c]);
      if (parts[c] == comm.rank()) mine[node] = 1;
    }
  std::vector<std::int64_t> ghosts;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    if (parts[c] == comm.rank()) continue;
    bool touches = false;
    for (std::size_t v = 0; v < 8; ++v)
      touches |= mine[static_cast<std::size_t>(grid[c * 8 + v])] != 0;
    if (touches) ghosts.push_back(static_cast<std::int64_t>(c));
  }
  EXPECT_EQ(
      std::vector<std::int64_t>(g.part.cell_ids.begin() + static_cast<std::ptrdiff_t>(n_owned),
                                g.part.cell_ids.end()),
      ghosts);
  std::int64_t owned_nodes = 0;
  for (std::size_t v = 0; v < g.part.node_ids.size(); ++v) {
    const auto node = static_cast<std::size_t>(g.part.node_ids[v]);
    EXPECT_EQ(g.owns_node[v] != 0, lowest[node] == comm.rank()) << "node " << node;
    owned_nodes += g.owns_node[v];
    EXPECT_EQ(g.part.data.points[v], grid_point(static_cast<std::int64_t>(node)));
  }
  EXPECT_EQ(dist::sum_in_rank_order(comm, owned_nodes), static_cast<std::int64_t>(n_nodes));
  // Every ghost's nodes are held, with the grid's connectivity.
  for (std::size_t c = 0; c < g.part.cell_ids.size(); ++c)
    for (std::size_t v = 0; v < 8; ++v)
      EXPECT_EQ(g.part.node_ids[g.part.data.cells[c * 8 + v].idx()],
                grid[static_cast<std::size_t>(g.part.cell_ids[c]) * 8 + v]);
}

// Two layers: the ghosts are the other ranks' cells using a node of this rank's cells or of
// the first layer's; the nodes' owners stay those of one layer.
TEST(PartitionOnRanks, TwoGhostLayersHoldTheCellsTwoRingsAway) {
  const auto& comm = dynamic_cast<const dist::MpiCommunicator&>(test::world());
  const io::MeshPart part = grid_part();
  const std::vector<int> to =
      dist::scotch_partition(comm, dist::dual_graph(comm, 8, cell_nodes(part)), comm.size());
  const io::MeshPart owned = io::migrate(comm, part, to);
  const io::GhostedPart one = io::with_ghost_layers(comm, owned);
  const io::GhostedPart two = io::with_ghost_layers(comm, owned, 2);
  const std::vector<int> parts = dist::all_gather_values(comm, to);
  const std::vector<std::int64_t> grid = grid_cells();
  std::vector<char> near((side + 1) * (side + 1) * (side + 1),
                         0);  // nodes of the cells held in `one`
  for (const std::int64_t c : one.part.cell_ids)
    for (std::size_t v = 0; v < 8; ++v) near[static_cast<std::size_t>(grid[8 * c + v])] = 1;
  std::vector<std::int64_t> ghosts;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    bool touches = false;
    for (std::size_t v = 0; v < 8; ++v) touches |= near[static_cast<std::size_t>(grid[c * 8 + v])];
    if (parts[c] != comm.rank() && touches) ghosts.push_back(static_cast<std::int64_t>(c));
  }
  ASSERT_EQ(two.owned_cells, one.owned_cells);
  EXPECT_EQ(std::vector<std::int64_t>(two.part.cell_ids.begin() + two.owned_cells,
                                      two.part.cell_ids.end()),
            ghosts);
  EXPECT_GT(two.part.cell_ids.size(), one.part.cell_ids.size());
  for (std::size_t v = 0; v < two.part.node_ids.size(); ++v) {
    const auto it =
        std::lower_bound(one.part.node_ids.begin(), one.part.node_ids.end(), two.part.node_ids[v]);
    const bool in_one = it != one.part.node_ids.end() && *it == two.part.node_ids[v];
    EXPECT_EQ(two.owns_node[v] != 0,
              in_one && one.owns_node[static_cast<std::size_t>(it - one.part.node_ids.begin())])
        << "node " << two.part.node_ids[v];
  }
}

}  // namespace
}  // namespace hexadapt
