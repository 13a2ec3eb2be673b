#include "hexadapt/adapt/interface_pillow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "adapt/adapt_cases.h"
#include "adapt/generated_case.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/mesh/mesh_check.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

// A 3D generated case's staircase, pillowed on the unmoved grid.
template <class F>
void on_case(const test::GeneratedCase& c, F&& check) {
  test::with_generated_case(
      c, [&](const auto& grid, const Fractions& f, const IdVector<CellId, int>& m) {
        if constexpr (std::decay_t<decltype(grid)>::dim == 3) {
          const Targets t = compute_targets(grid, f, m, boundary_constraints(grid));
          check(grid, m, f.n_materials(), t.has, size_criterion(grid, 0.1));
        }
      });
}

// The asteroid at 20^3: some layer cells fail at its staircase's concave corners.
template <class F>
void on_asteroid(F&& check) {
  on_case({"asteroid", {20, 20, 20}}, std::forward<F>(check));
}

index_t failing_cells(const HexMesh& mesh, const SizeCriterion& size, double threshold) {
  index_t n = 0;
  for (CellId c : id_range<CellId>(mesh.n_cells())) n += cell_score(mesh, c, size) < threshold;
  return n;
}

TEST(InterfacePillow, CarvesWhereCellsFailOrKeepsThemForTheMovesToMend) {
  on_asteroid([](const HexMesh& grid, const IdVector<CellId, int>& m, int n_materials,
                 const IdVector<NodeId, char>& fixed, const SizeCriterion& size) {
    InterfacePillowOptions o;
    const auto carved = pillow_interfaces(grid, m, n_materials, fixed, size, o);
    index_t left_out = 0;
    for (const InterfacePillowAttempt& a : carved.attempts) {
      left_out += a.left_out;
      EXPECT_EQ(a.failing, 0);
    }
    EXPECT_GT(left_out, 0);
    const SizeCriterion carved_size = size.remapped(carved.cell_origin.raw());
    EXPECT_EQ(failing_cells(carved.mesh, carved_size, default_threshold), 0);

    o.keep_failing = true;
    const auto kept = pillow_interfaces(grid, m, n_materials, fixed, size, o);
    index_t failing = 0;
    for (const InterfacePillowAttempt& a : kept.attempts) {
      EXPECT_TRUE(a.kept);
      EXPECT_EQ(a.rounds, 1);
      EXPECT_EQ(a.left_out, 0);
      failing += a.failing;
    }
    EXPECT_GT(failing, 0);
    EXPECT_GT(kept.mesh.n_cells(), carved.mesh.n_cells());
    const SizeCriterion kept_size = size.remapped(kept.cell_origin.raw());
    EXPECT_EQ(failing_cells(kept.mesh, kept_size, default_threshold), failing);
    // The nodes with a target never move.
    for (NodeId v : id_range<NodeId>(grid.n_nodes()))
      if (fixed[v]) {
        EXPECT_EQ(kept.mesh.point(v), grid.point(v));
      }
  });
}

// The drop touching the pool (balldrop at 16^3, t = 1): the air, pillowed first with its
// sheets between the drop and the pool, keeps failing cells. Each material counts those of
// its own layer and ring, not those of a layer kept failing before it (the pool and the drop
// used to report the air's).
TEST(InterfacePillow, EachMaterialCountsItsOwnFailingCells) {
  on_case({"balldrop", {16, 16, 16}, 1.0},
          [](const HexMesh& grid, const IdVector<CellId, int>& m, int n_materials,
             const IdVector<NodeId, char>& fixed, const SizeCriterion& size) {
            InterfacePillowOptions o;
            o.keep_failing = true;
            o.sheet_layers = true;
            const auto kept = pillow_interfaces(grid, m, n_materials, fixed, size, o);
            const SizeCriterion kept_size = size.remapped(kept.cell_origin.raw());
            std::vector<index_t> own(static_cast<std::size_t>(n_materials), 0);
            for (CellId c : id_range<CellId>(kept.mesh.n_cells()))
              own[static_cast<std::size_t>(kept.material[c])] +=
                  cell_score(kept.mesh, c, kept_size) < default_threshold;
            EXPECT_GT(own[0], 0);
            for (const InterfacePillowAttempt& a : kept.attempts)
              EXPECT_EQ(a.failing, own[static_cast<std::size_t>(a.material)]) << a.material;
          });
}

// The same case with the sheets left out: the air's cells one cell thick between the drop
// and the pool get no layer, and no layer cell fails any more.
TEST(InterfacePillow, LeavesSheetsBetweenTwoMaterialsOut) {
  on_case({"balldrop", {16, 16, 16}, 1.0}, [](const HexMesh& grid, const IdVector<CellId, int>& m,
                                              int n_materials, const IdVector<NodeId, char>& fixed,
                                              const SizeCriterion& size) {
    InterfacePillowOptions o;
    o.keep_failing = true;
    const auto r = pillow_interfaces(grid, m, n_materials, fixed, size, o);
    index_t sheets = 0, failing = 0;
    for (const InterfacePillowAttempt& a : r.attempts) {
      EXPECT_TRUE(a.kept) << a.material;
      EXPECT_EQ(a.left_out, a.sheet_cells) << a.material;
      sheets += a.sheet_cells;
      failing += a.failing;
    }
    EXPECT_GT(sheets, 0);
    EXPECT_EQ(failing, 0);
    EXPECT_EQ(failing_cells(r.mesh, size.remapped(r.cell_origin.raw()), default_threshold), 0);
  });
}

// Which cells are sheets: one cell thick across two facing faces, between two materials that
// differ from each other. Material 1 in the middle layer of a 4 x 3 x 5 grid is one between
// 0 and 2 (every cell of it is left out); between 0 and 0 it is not (none is); in 2D the same
// holds for a row of quads.
TEST(InterfacePillow, SheetsAreOneCellBetweenTwoOtherMaterials) {
  const IdVector<NodeId, char> none3(static_cast<std::size_t>(make_hex_grid(4, 3, 5).n_nodes()), 0);
  for (const int above : {2, 0}) {
    const HexMesh grid = make_hex_grid(4, 3, 5);
    IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
    for (CellId c : id_range<CellId>(grid.n_cells())) {
      const int k = static_cast<int>(c.value()) / 12;
      material[c] = k == 2 ? 1 : (k > 2 ? above : 0);
    }
    const auto r = pillow_interfaces(grid, material, 3, none3, size_criterion(grid, 0.1));
    EXPECT_EQ(r.attempts[1].sheet_cells, above == 2 ? 12 : 0) << above;
    EXPECT_EQ(r.attempts[0].sheet_cells + r.attempts[2].sheet_cells, 0);
    EXPECT_TRUE(check_mesh(r.mesh).ok());
  }
  const QuadMesh quads = make_quad_grid(4, 5);
  IdVector<CellId, int> material(static_cast<std::size_t>(quads.n_cells()), 0);
  for (CellId c : id_range<CellId>(quads.n_cells())) {
    const int j = static_cast<int>(c.value()) / 4;
    material[c] = j == 2 ? 1 : (j > 2 ? 2 : 0);
  }
  const IdVector<NodeId, char> none2(static_cast<std::size_t>(quads.n_nodes()), 0);
  const auto r = pillow_interfaces(quads, material, 3, none2, size_criterion(quads, 0.1));
  EXPECT_EQ(r.attempts[1].sheet_cells, 4);
  InterfacePillowOptions o;
  o.sheet_layers = true;
  EXPECT_EQ(pillow_interfaces(quads, material, 3, none2, size_criterion(quads, 0.1), o)
                .attempts[1]
                .sheet_cells,
            0);
}

TEST(InterfacePillow, LeavesTheRegionsOutAroundTheCellsGiven) {
  on_asteroid([](const HexMesh& grid, const IdVector<CellId, int>& m, int n_materials,
                 const IdVector<NodeId, char>& fixed, const SizeCriterion& size) {
    InterfacePillowOptions o;
    o.keep_failing = true;
    o.carve = 1;
    // The cells of the first layer that fail come from these input cells.
    const auto first = pillow_interfaces(grid, m, n_materials, fixed, size, o);
    const SizeCriterion first_size = size.remapped(first.cell_origin.raw());
    std::vector<CellId> around;
    for (CellId c : id_range<CellId>(first.mesh.n_cells()))
      if (cell_score(first.mesh, c, first_size) < default_threshold)
        around.push_back(first.cell_origin[c]);
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    ASSERT_FALSE(around.empty());

    const auto again = pillow_interfaces(grid, m, n_materials, fixed, size, o, {}, around);
    index_t left_out = 0;
    for (const InterfacePillowAttempt& a : again.attempts) left_out += a.left_out;
    EXPECT_GE(left_out, static_cast<index_t>(around.size()));
    // No layer cell is inflated from a cell given, nor from a cell sharing a node with one.
    IdVector<CellId, char> near(static_cast<std::size_t>(grid.n_cells()), 0);
    for (CellId c : around)
      for (NodeId v : grid.cell_nodes(c))
        for (CellId o2 : grid.node_cells(v))
          if (m[o2] == m[c]) near[o2] = 1;
    for (CellId c : id_range<CellId>(again.mesh.n_cells()))
      if (c.value() >= grid.n_cells()) {
        EXPECT_FALSE(near[again.cell_origin[c]]) << c.value();
      }
  });
}

// A region of two cells that share only an edge, joined by cells around both of its ends: no
// layer follows it (pillow.h). The cells around that edge are carved out and the rest of
// the region gets its layer; the material used to stay unpillowed.
TEST(InterfacePillow, CarvesWhereTheRegionTouchesItselfAlongAnEdge) {
  const HexMesh grid = make_hex_grid(5, 5, 5);
  IdVector<CellId, int> material(static_cast<std::size_t>(grid.n_cells()), 0);
  const std::array<std::array<int, 3>, 8> cells{
      {{1, 1, 2}, {2, 2, 2}, {1, 1, 3}, {2, 1, 3}, {2, 2, 3}, {1, 1, 1}, {2, 1, 1}, {2, 2, 1}}};
  for (const auto& [i, j, k] : cells) material[CellId(i + 5 * (j + 5 * k))] = 1;
  const IdVector<NodeId, char> fixed(static_cast<std::size_t>(grid.n_nodes()), 0);
  InterfacePillowOptions o;
  o.carve = 0;
  const auto r = pillow_interfaces(grid, material, 2, fixed, size_criterion(grid, 0.1), o);
  ASSERT_EQ(r.attempts.size(), 2u);
  const InterfacePillowAttempt& region = r.attempts[1];
  EXPECT_TRUE(region.kept);
  EXPECT_EQ(region.left_out, 2);  // the two cells that share the edge
  EXPECT_GT(region.layer_cells, 0);
  const MeshCheckResult check = check_mesh(r.mesh);
  EXPECT_TRUE(check.ok());
}

}  // namespace
}  // namespace hexadapt
