// Small pieces given to the material around them (islands.h): a lone cell of noise goes to
// its surroundings, neighbouring small pieces both go to the material around them, pieces
// with no larger neighbour stay (counted), and through assign_materials injected one-cell
// islands leave no small piece in the final assignment.
#include <gtest/gtest.h>

#include <random>

#include "hexadapt/assign/assign.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::assign {
namespace {

CellId cell(int i, int j, int nx) {
  return CellId(j * nx + i);
}

// Two materials: b inside the disk of radius 0.3 around (0.5, 0.5), a outside.
Fractions disk_fractions(const QuadMesh& mesh, int nx) {
  Fractions f(mesh.n_cells(), {"a", "b"});
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const double x = (c.value() % nx + 0.5) / nx, y = (c.value() / nx + 0.5) / nx;
    const bool in = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) < 0.09;
    f(c, 0) = in ? 0 : 1;
    f(c, 1) = in ? 1 : 0;
  }
  return f;
}

TEST(Islands, ALoneCellGoesToTheMaterialAroundIt) {
  const QuadMesh mesh = make_quad_grid(5, 5, Vec3::Zero(), Vec3::Constant(0.2));
  Fractions f(mesh.n_cells(), {"a", "b", "c"});
  for (CellId c : id_range<CellId>(mesh.n_cells())) f(c, 0) = 1;
  f(cell(2, 2, 5), 0) = 0.3, f(cell(2, 2, 5), 1) = 0.7;  // a lone b in a
  f(cell(3, 2, 5), 0) = 0.4, f(cell(3, 2, 5), 2) = 0.6;  // a lone c beside it
  CellMaterials labels = majority_materials(f);
  ASSERT_EQ(count_small_pieces(mesh, labels, 2), 2);
  const IslandResult r = remove_islands(mesh, f, labels, 2);
  EXPECT_EQ(r.islands, 2);
  EXPECT_EQ(r.cells, 2);
  EXPECT_EQ(r.left, 0);
  for (int m : labels) EXPECT_EQ(m, 0);
  // Off at 0 and 1: nothing is a piece of fewer than one cell.
  CellMaterials again = majority_materials(f);
  EXPECT_EQ(remove_islands(mesh, f, again, 1).islands, 0);
  EXPECT_EQ(again.raw(), majority_materials(f).raw());
}

TEST(Islands, APieceWithOnlySmallNeighboursStays) {
  const QuadMesh mesh = make_quad_grid(2, 1);
  Fractions f(mesh.n_cells(), {"a", "b"});
  f(CellId(0), 0) = 1;
  f(CellId(1), 1) = 1;
  CellMaterials labels = majority_materials(f);
  const IslandResult r = remove_islands(mesh, f, labels, 5);
  EXPECT_EQ(r.islands, 0);
  EXPECT_EQ(r.left, 2);
  EXPECT_EQ(labels[CellId(0)], 0);
  EXPECT_EQ(labels[CellId(1)], 1);
}

// 20 one-cell islands injected into a disk case (a cell's majority flipped): without the
// option most survive the correction as small pieces; with --min-island 3 none does, and
// the disk itself is kept.
TEST(Islands, InjectedIslandsLeaveNoSmallPiece) {
  const int n = 30;
  const QuadMesh mesh = make_quad_grid(n, n, Vec3::Zero(), Vec3::Constant(1.0 / n));
  Fractions f = disk_fractions(mesh, n);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, n * n - 1);
  for (int k = 0; k < 20; ++k) {
    const CellId c(pick(rng));
    const int m = f(c, 0) > 0.5 ? 1 : 0;
    f(c, m) = 0.9, f(c, 1 - m) = 0.1;
  }
  const AssignResult plain = assign_materials(mesh, f);
  ASSERT_TRUE(plain.correction.solved);
  const index_t injected = count_small_pieces(mesh, plain.majority, 3);
  EXPECT_GE(injected, 10);  // the others touch the disk's edge or each other
  EXPECT_GE(count_small_pieces(mesh, plain.correction.labels, 3), 10);
  AssignOptions o;
  o.min_island = 3;
  const AssignResult r = assign_materials(mesh, f, o);
  ASSERT_TRUE(r.correction.solved);
  EXPECT_EQ(r.islands.islands, injected);
  EXPECT_EQ(r.islands.left, 0);
  EXPECT_EQ(r.small_pieces_final, 0);
  EXPECT_EQ(count_small_pieces(mesh, r.correction.labels, 3), 0);
  index_t disk = 0;
  for (int m : r.correction.labels) disk += m == 1;
  EXPECT_GT(disk, 200);  // pi 0.09 n^2 = 254 cells
}

}  // namespace
}  // namespace hexadapt::assign
