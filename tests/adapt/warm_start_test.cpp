#include "hexadapt/adapt/warm_start.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "adapt/generated_case.h"
#include "hexadapt/adapt/interface_pillow.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

// The asteroid at 16^3, its interfaces pillowed with their failing cells kept (as the runs of
// the mending pillow them), with no cell or with `left_out` left out.
template <class F>
void on_pillowed_asteroid(F&& check) {
  test::with_generated_case({"asteroid", {16, 16, 16}}, [&](const auto& grid, const Fractions& f,
                                                            const IdVector<CellId, int>& m) {
    if constexpr (std::decay_t<decltype(grid)>::dim == 3) {
      const Targets t = compute_targets(grid, f, m, boundary_constraints(grid));
      InterfacePillowOptions o;
      o.keep_failing = true;
      auto pillowed = [&](const std::vector<CellId>& left_out) {
        return pillow_interfaces(grid, m, f.n_materials(), t.has, size_criterion(grid, 0.1), o, {},
                                 left_out);
      };
      check(grid, pillowed);
    }
  });
}

// Moves every node by a small amount of its own, so that each point names its node.
void shift_all(HexMesh& mesh) {
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    mesh.set_point(v, mesh.point(v) + 1e-4 * Vec3(1.0 + v.value() % 7, 1.0 + v.value() % 5,
                                                  1.0 + v.value() % 3));
}

TEST(WarmStart, EveryNodeOfTheSamePillowingIsNamedOnceAndStartsWarm) {
  on_pillowed_asteroid([](const HexMesh&, const auto& pillowed) {
    auto before = pillowed({});
    auto now = pillowed({});
    ASSERT_EQ(before.node_origin.size(), static_cast<std::size_t>(before.mesh.n_nodes()));
    const NodePlaces here = node_places(now.mesh, now.node_origin, now.cell_origin);
    EXPECT_EQ(std::set<std::uint64_t>(here.name.begin(), here.name.end()).size(), here.name.size());
    shift_all(before.mesh);
    const NodePlaces there = node_places(before.mesh, before.node_origin, before.cell_origin);
    const std::vector<NodeId> start = warm_start(now.mesh, here, there);
    EXPECT_TRUE(start.empty());
    for (NodeId v : id_range<NodeId>(now.mesh.n_nodes())) {
      EXPECT_EQ(now.mesh.point(v), before.mesh.point(v));
    }
  });
}

TEST(WarmStart, NodesAroundCellsLeftOutStartColdAndTheOthersWhereTheRunBeforeEnded) {
  on_pillowed_asteroid([](const HexMesh& grid, const auto& pillowed) {
    auto before = pillowed({});
    // An interface cell of the rock: its layer changes when it is left out.
    CellId out;
    for (CellId c : id_range<CellId>(before.mesh.n_cells()))
      if (c.value() >= grid.n_cells()) {
        out = before.cell_origin[c];
        break;
      }
    ASSERT_TRUE(out.valid());
    auto now = pillowed({out});
    ASSERT_NE(now.mesh.n_cells(), before.mesh.n_cells());
    shift_all(before.mesh);
    const NodePlaces there = node_places(before.mesh, before.node_origin, before.cell_origin);
    const NodePlaces here = node_places(now.mesh, now.node_origin, now.cell_origin);
    const HexMesh unmoved = now.mesh;
    const std::vector<NodeId> start = warm_start(now.mesh, here, there);
    ASSERT_FALSE(start.empty());
    EXPECT_LT(start.size(), 400u);
    Vec3 centre = Vec3::Zero();
    for (NodeId v : grid.cell_nodes(out)) centre += grid.point(v) / 8.0;
    const auto corners = grid.cell_nodes(out);
    const double h = (grid.point(corners[7]) - grid.point(corners[0])).norm();
    index_t warm = 0;
    for (NodeId v : id_range<NodeId>(now.mesh.n_nodes())) {
      const bool moved = now.mesh.point(v) != unmoved.point(v);
      const bool started = std::binary_search(start.begin(), start.end(), v);
      // A warm node takes the point the run before gave to its namesake: a shifted point.
      if (moved) {
        ++warm;
        EXPECT_EQ(
            std::count(before.mesh.points().begin(), before.mesh.points().end(), now.mesh.point(v)),
            1);
      }
      // Far from the cell left out, every node is warm and is not started from.
      if ((unmoved.point(v) - centre).norm() > 4 * h) {
        EXPECT_TRUE(moved) << v.value();
        EXPECT_FALSE(started) << v.value();
      }
      // The new nodes of the cell left out have no namesake.
      if (!moved) {
        EXPECT_TRUE(started) << v.value();
      }
    }
    EXPECT_GT(warm, now.mesh.n_nodes() - 400);
  });
}

TEST(WarmStart, ANodeOfNoCellWithoutANamesakeStaysWhereItIs) {
  const HexMesh grid = make_hex_grid(2, 2, 2);
  std::vector<Vec3> points = grid.points();
  points.emplace_back(5.0, 5.0, 5.0);
  std::vector<HexMesh::CellNodes> cells;
  for (CellId c : id_range<CellId>(grid.n_cells())) cells.push_back(grid.cell_nodes(c));
  HexMesh mesh(points, cells);
  auto identity = [](index_t n_nodes, index_t n_cells) {
    std::pair<IdVector<NodeId, NodeId>, IdVector<CellId, CellId>> o;
    for (NodeId v : id_range<NodeId>(n_nodes)) o.first.push_back(v);
    for (CellId c : id_range<CellId>(n_cells)) o.second.push_back(c);
    return o;
  };
  HexMesh shifted = grid;
  shift_all(shifted);
  const auto g = identity(grid.n_nodes(), grid.n_cells());
  const auto m = identity(mesh.n_nodes(), mesh.n_cells());
  const std::vector<NodeId> start = warm_start(mesh, node_places(mesh, m.first, m.second),
                                               node_places(shifted, g.first, g.second));
  EXPECT_TRUE(start.empty());
  EXPECT_EQ(mesh.point(NodeId(grid.n_nodes())), Vec3(5.0, 5.0, 5.0));
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) {
    EXPECT_EQ(mesh.point(v), shifted.point(v));
  }
}

}  // namespace
}  // namespace hexadapt
