// Materials nowhere the majority (keep_materials.h): without the option they vanish; kept,
// they take the cells where they are most present, as many as their volume fills, and keep
// them through the manifold correction.
#include <gtest/gtest.h>

#include "hexadapt/assign/assign.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::assign {
namespace {

// a on the left, b on the right of 10 x 10 cells; c, 0.3 to 0.45 in a 2 x 2 block in a's
// half, never the majority there (a keeps the rest).
Fractions three_materials(const QuadMesh& mesh) {
  Fractions f(mesh.n_cells(), {"a", "b", "c"});
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const int i = c.value() % 10, j = c.value() / 10;
    f(c, i < 5 ? 0 : 1) = 1;
    if (i >= 1 && i <= 2 && j >= 4 && j <= 5) {
      const double share = i == 1 && j == 4 ? 0.45 : 0.3;
      f(c, 2) = share, f(c, 0) = 1 - share;
    }
  }
  return f;
}

TEST(KeepMaterials, AMaterialNowhereTheMajorityKeepsTheCellsWhereItIsMostPresent) {
  const QuadMesh mesh = make_quad_grid(10, 10);
  const Fractions f = three_materials(mesh);
  const AssignResult plain = assign_materials(mesh, f);
  ASSERT_TRUE(plain.correction.solved);
  EXPECT_TRUE(plain.balance[2].vanished());
  AssignOptions o;
  o.keep_materials = true;
  const AssignResult r = assign_materials(mesh, f, o);
  ASSERT_TRUE(r.correction.solved);
  ASSERT_EQ(r.kept.size(), 1u);
  EXPECT_EQ(r.kept[0].material, 2);
  // Volume 0.45 + 3 x 0.3 = 1.35 cells: one cell, the one where c is most present.
  EXPECT_EQ(r.kept[0].cells, 1);
  EXPECT_EQ(r.correction.labels[CellId(4 * 10 + 1)], 2);
  EXPECT_FALSE(r.balance[2].vanished());
  EXPECT_EQ(r.balance[2].assigned_cells, 1);
  EXPECT_EQ(r.majority.raw(), plain.majority.raw());  // the majority itself is eq. (2)
}

// A material with no volume anywhere is not kept; nor is a cell taken that is its
// material's last.
TEST(KeepMaterials, NeitherAnAbsentMaterialNorAnotherOnesLastCell) {
  const QuadMesh mesh = make_quad_grid(2, 1);
  Fractions f(mesh.n_cells(), {"a", "b", "c", "d"});
  f(CellId(0), 0) = 0.6, f(CellId(0), 2) = 0.4;
  f(CellId(1), 1) = 1;
  CellMaterials labels = majority_materials(f);
  EXPECT_TRUE(keep_vanished_materials(mesh, f, labels).empty());
  EXPECT_EQ(labels[CellId(0)], 0);
  EXPECT_EQ(labels[CellId(1)], 1);
}

}  // namespace
}  // namespace hexadapt::assign
