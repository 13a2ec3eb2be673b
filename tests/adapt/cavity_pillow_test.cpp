// Cavity pillowing (paper sec. 5.2, Alg. 5) on hand-built grids: a cavity published at its
// full range, one that must shrink (the paper's Fig. 16: a poor cell at the edge of the big
// cavity), one that never succeeds and leaves the mesh untouched.
#include "hexadapt/adapt/cavity_pillow.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"
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
  StepSettings shared;
  shared.threshold = 0.7;
  const auto r = cavity_pillow(grid, material, 2, {grid_node(5, 5, 10)}, {}, shared);
  ASSERT_EQ(r.attempts.size(), 2u);
  EXPECT_EQ(r.attempts[0].material, 0);
  EXPECT_FALSE(r.attempts[0].published);
  EXPECT_EQ(r.attempts[0].range, 3);
  EXPECT_EQ(r.attempts[0].cells, 35);  // the 6 x 6 block less the other material's cell
  EXPECT_LT(r.attempts[0].min_quality, 0.7);
  EXPECT_TRUE(r.attempts[1].published) << r.attempts[1].min_quality;
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
  StepSettings shared;
  shared.threshold = 0.999;  // no layer cell is a perfect cube
  const NodeId seed(5 * 121 + 5 * 11 + 5);
  const auto r = cavity_pillow(grid, material, 1, {seed}, o, shared);
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

// The seeds of a test: the nodes where cells of two materials meet, every `every`-th one.
template <class M>
std::vector<NodeId> interface_nodes(const M& mesh, const IdVector<CellId, int>& material,
                                    int every) {
  std::vector<NodeId> out;
  int k = 0;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    const auto cells = mesh.node_cells(v);
    const bool mixed = std::any_of(cells.begin(), cells.end(),
                                   [&](CellId c) { return material[c] != material[cells[0]]; });
    if (mixed && k++ % every == 0) out.push_back(v);
  }
  return out;
}

// Pillowing each cavity in its patch must give exactly what pillowing it in the whole mesh
// gives: same attempts, same published mesh to the last bit.
template <class M>
void expect_same_as_whole_mesh(const M& mesh, const IdVector<CellId, int>& material,
                               int n_materials, const std::vector<NodeId>& seeds, CavityOptions o) {
  const auto local = cavity_pillow(mesh, material, n_materials, seeds, o);
  o.whole_mesh = true;
  const auto whole = cavity_pillow(mesh, material, n_materials, seeds, o);
  ASSERT_EQ(local.attempts.size(), whole.attempts.size());
  for (std::size_t k = 0; k < local.attempts.size(); ++k) {
    const CavityAttempt& a = local.attempts[k];
    const CavityAttempt& b = whole.attempts[k];
    EXPECT_EQ(a.seeds, b.seeds) << "attempt " << k;
    EXPECT_EQ(a.cells, b.cells) << "attempt " << k;
    EXPECT_EQ(a.published, b.published) << "attempt " << k;
    EXPECT_EQ(a.min_quality, b.min_quality) << "attempt " << k;
  }
  EXPECT_GT(local.n_published, 0);
  EXPECT_EQ(local.failed_seeds, whole.failed_seeds);
  ASSERT_EQ(local.mesh.n_nodes(), whole.mesh.n_nodes());
  ASSERT_EQ(local.mesh.n_cells(), whole.mesh.n_cells());
  for (NodeId v : id_range<NodeId>(local.mesh.n_nodes()))
    EXPECT_EQ(local.mesh.point(v), whole.mesh.point(v)) << "node " << v.value();
  for (CellId c : id_range<CellId>(local.mesh.n_cells()))
    EXPECT_EQ(local.mesh.cell_nodes(c), whole.mesh.cell_nodes(c)) << "cell " << c.value();
  EXPECT_EQ(local.material.raw(), whole.material.raw());
  EXPECT_EQ(local.node_origin.raw(), whole.node_origin.raw());
  EXPECT_TRUE(check_mesh(local.mesh).ok());
  EXPECT_GE(min_quality(local.mesh), StepSettings{}.threshold);
}

TEST(CavityPillow, PatchesGiveTheWholeMeshResult2D) {
  const QuadMesh grid = make_quad_grid(16, 14, test::jittered_points(16, 14, 0, 0.15, 3));
  IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  for (CellId c : id_range<CellId>(grid.n_cells())) {
    const Vec3 x = cell_centroid(grid, c);
    material[c] = (x - Vec3(6.3, 7.1, 0)).norm() < 3.6 ? 1 : (x.x() > 11.5 ? 2 : 0);
  }
  CavityOptions o;
  o.range = 2;
  expect_same_as_whole_mesh(grid, material, 3, interface_nodes(grid, material, 5), o);
}

TEST(CavityPillow, PatchesGiveTheWholeMeshResult3D) {
  const HexMesh grid = make_hex_grid(7, 7, 6);
  IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  for (CellId c : id_range<CellId>(grid.n_cells()))
    material[c] = (cell_centroid(grid, c) - Vec3(3.6, 3.4, 2.9)).norm() < 2.1;
  CavityOptions o;
  o.range = 2;
  expect_same_as_whole_mesh(grid, material, 2, interface_nodes(grid, material, 9), o);
}

// Material 0 holds two cells that touch along an edge only, joined around both ends of the
// edge by cells above and below: pillowed whole, the layer cannot be a mesh (pillow_test),
// so the range-2 cavity is rejected without an error. At range 1 the seed (the edge's top
// node) only has the cells joined at that end: the layer is built, but the one copy of the
// seed both touching cells must share cannot make them both good, so the seed is given up
// and the mesh stays as it was.
TEST(CavityPillow, RejectsACavityTouchingItselfAlongAnEdge) {
  const HexMesh grid = make_hex_grid(5, 5, 5);
  IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 1);
  for (int k = 1; k <= 3; ++k)
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{1, 1}, {2, 2}, {2, 1}})
      material[CellId(i + 5 * (j + 5 * k))] = (k == 2 && i == 2 && j == 1) ? 1 : 0;
  CavityOptions o;
  o.range = 2;
  StepSettings shared;
  shared.threshold = 0.2;
  const NodeId top(2 + 6 * (2 + 6 * 3));  // node (2, 2, 3)
  const auto r = cavity_pillow(grid, material, 2, {top}, o, shared);
  ASSERT_EQ(r.attempts.size(), 3u);  // material 0 at ranges 2 and 1, then material 1
  EXPECT_EQ(r.attempts[0].material, 0);
  EXPECT_EQ(r.attempts[0].range, 2);
  EXPECT_EQ(r.attempts[0].cells, 8);
  EXPECT_FALSE(r.attempts[0].published);
  EXPECT_EQ(r.attempts[0].min_quality, -1.0);  // no layer could be built
  EXPECT_EQ(r.attempts[1].range, 1);
  EXPECT_EQ(r.attempts[1].cells, 5);
  EXPECT_FALSE(r.attempts[1].published);
  EXPECT_GT(r.attempts[1].min_quality, -1.0);  // built, but too poor
  EXPECT_LT(r.attempts[1].min_quality, 0.2);
  EXPECT_EQ(r.attempts[2].material, 1);
  EXPECT_TRUE(r.attempts[2].published);
  EXPECT_EQ(r.failed_seeds, std::vector<NodeId>{top});
  EXPECT_TRUE(check_mesh(r.mesh).ok());
  EXPECT_GE(min_quality(r.mesh), 0.2);
}
}  // namespace
}  // namespace hexadapt
