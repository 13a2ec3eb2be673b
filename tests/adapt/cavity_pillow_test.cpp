// Cavity pillowing (paper sec. 5.2, Alg. 5) on hand-built grids: a cavity published at its
// full range, one that must shrink (the paper's Fig. 16: a poor cell at the edge of the big
// cavity), one that never succeeds and leaves the mesh untouched.
#include "hexadapt/adapt/cavity_pillow.h"

#include <gtest/gtest.h>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/mesh_check.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

NodeId grid_node(int i, int j, int nx) {
  return NodeId(j * (nx + 1) + i);
}

TEST(CavityPillow, PublishesAtFullRange) {
  const QuadMesh grid = make_quad_grid(10, 10);
  const IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  const NodeId seed = grid_node(5, 5, 10);
  const auto r = cavity_pillow(grid, material, 1, {seed});
  ASSERT_EQ(r.attempts.size(), 1u);
  EXPECT_TRUE(r.attempts[0].published);
  EXPECT_EQ(r.attempts[0].range, 3);
  EXPECT_EQ(r.attempts[0].cells, 36);  // cells [2, 8) x [2, 8)
  EXPECT_EQ(r.n_published, 1);
  EXPECT_EQ(r.n_cells_added, 24);  // one layer cell per boundary edge of the 6 x 6 block
  EXPECT_EQ(r.mesh.n_cells(), 124);
  EXPECT_EQ(r.material.size(), 124u);
  EXPECT_TRUE(r.failed_seeds.empty());
  EXPECT_GE(min_quality(r.mesh), 0.3);
  EXPECT_TRUE(check_mesh(r.mesh).ok());
  // Input nodes keep their ids and their positions outside the cavity.
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) EXPECT_EQ(r.node_origin[v], v);
  EXPECT_EQ(r.mesh.point(grid_node(0, 0, 10)), grid.point(grid_node(0, 0, 10)));
}

// The paper's Fig. 16 situation: another material's corner cuts into the range-3 cavity, so
// it is L-shaped and the layer cells at its reentrant corner are poorer (0.665 after
// smoothing) than the threshold 0.7; the square range-2 cavity (0.707) stays clear of it.
TEST(CavityPillow, ShrinksToRangeTwo) {
  const QuadMesh grid = make_quad_grid(10, 10);
  IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  for (CellId c : id_range<CellId>(grid.n_cells()))
    material[c] = c.value() % 10 >= 7 && c.value() / 10 >= 7;
  CavityOptions o;
  o.threshold = 0.7;
  const auto r = cavity_pillow(grid, material, 2, {grid_node(5, 5, 10)}, o);
  ASSERT_EQ(r.attempts.size(), 2u);
  EXPECT_EQ(r.attempts[0].material, 0);
  EXPECT_FALSE(r.attempts[0].published);
  EXPECT_EQ(r.attempts[0].range, 3);
  EXPECT_EQ(r.attempts[0].cells, 35);  // the 6 x 6 block less the other material's cell
  EXPECT_LT(r.attempts[0].min_quality, 0.7);
  EXPECT_TRUE(r.attempts[1].published);
  EXPECT_EQ(r.attempts[1].range, 2);
  EXPECT_EQ(r.attempts[1].cells, 16);
  EXPECT_EQ(r.n_cells_added, 16);
  EXPECT_TRUE(r.failed_seeds.empty());
  EXPECT_GE(min_quality(r.mesh), 0.7);
  EXPECT_TRUE(check_mesh(r.mesh).ok());
}

TEST(CavityPillow, GivesUpAndLeavesTheMeshUnchanged) {
  const HexMesh grid = make_hex_grid(10, 10, 10);
  const IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  CavityOptions o;
  o.threshold = 0.999;  // no layer cell is a perfect cube
  const NodeId seed(5 * 121 + 5 * 11 + 5);
  const auto r = cavity_pillow(grid, material, 1, {seed}, o);
  ASSERT_EQ(r.attempts.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_FALSE(r.attempts[static_cast<std::size_t>(k)].published);
    EXPECT_EQ(r.attempts[static_cast<std::size_t>(k)].range, 3 - k);
  }
  EXPECT_EQ(r.failed_seeds, std::vector<NodeId>{seed});
  EXPECT_EQ(r.n_published, 0);
  ASSERT_EQ(r.mesh.n_nodes(), grid.n_nodes());
  ASSERT_EQ(r.mesh.n_cells(), grid.n_cells());
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) EXPECT_EQ(r.mesh.point(v), grid.point(v));
  for (CellId c : id_range<CellId>(grid.n_cells()))
    EXPECT_EQ(r.mesh.cell_nodes(c), grid.cell_nodes(c));
  EXPECT_EQ(r.material.raw(), material.raw());
}

TEST(CavityPillow, MergesOverlappingCavitiesAndKeepsMaterialsApart) {
  const QuadMesh grid = make_quad_grid(12, 6);
  IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  for (CellId c : id_range<CellId>(grid.n_cells())) material[c] = c.value() % 12 >= 6;
  CavityOptions o;
  o.range = 1;
  // Two seeds on the interface x = 6, two apart: their range-1 cavities share cells.
  const auto r = cavity_pillow(grid, material, 2, {grid_node(6, 2, 12), grid_node(6, 3, 12)}, o);
  ASSERT_EQ(r.attempts.size(), 2u);  // one merged cavity per material
  for (int m = 0; m < 2; ++m) {
    const auto& a = r.attempts[static_cast<std::size_t>(m)];
    EXPECT_EQ(a.material, m);
    EXPECT_EQ(a.seeds.size(), 2u);
    EXPECT_EQ(a.cells, 3);
    EXPECT_TRUE(a.published);
  }
  // Each 3-cell cavity gets 3 + 2 + 3 layer cells (edges on the domain boundary: none).
  EXPECT_EQ(r.n_cells_added, 16);
  EXPECT_TRUE(check_mesh(r.mesh).ok());
  CavityOptions bad;
  bad.range = 0;
  EXPECT_THROW(cavity_pillow(grid, material, 2, {}, bad), OptionError);
}

}  // namespace
}  // namespace hexadapt
