#include "hexadapt/mesh/plane_cut.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

// Unit square cut by x + y >= s: the corner triangle below has area s^2 / 2 for s <= 1.
TEST(PlaneCut, SquareCutByADiagonalLine) {
  const QuadMesh mesh = make_quad_grid(1, 1);
  const Vec3 n(1, 1, 0);
  for (double s : {0.0, 0.25, 0.6, 1.0})
    EXPECT_NEAR(volume_above_plane(mesh, CellId(0), n, s), 1 - s * s / 2, 1e-14) << s;
  EXPECT_NEAR(volume_above_plane(mesh, CellId(0), n, 1.5), 0.125, 1e-14);
  EXPECT_EQ(volume_above_plane(mesh, CellId(0), n, 2.5), 0.0);
}

// Unit cube cut by x + y + z >= s: the corner tet below has volume s^3 / 6 for s <= 1, and
// by symmetry the part above s = 3 - r is r^3 / 6. Every tet of the split is cut.
TEST(PlaneCut, CubeCutByAnObliquePlane) {
  const HexMesh mesh = make_hex_grid(1, 1, 1);
  const Vec3 n(1, 1, 1);
  for (double s : {0.0, 0.3, 0.8, 1.0})
    EXPECT_NEAR(volume_above_plane(mesh, CellId(0), n, s), 1 - s * s * s / 6, 1e-14) << s;
  for (double r : {0.2, 0.9})
    EXPECT_NEAR(volume_above_plane(mesh, CellId(0), n, 3 - r), r * r * r / 6, 1e-14);
  // The middle plane halves the cube.
  EXPECT_NEAR(volume_above_plane(mesh, CellId(0), n, 1.5), 0.5, 1e-14);
}

TEST(PlaneCut, OffsetForShareRecoversTheShare) {
  const HexMesh mesh = make_hex_grid(1, 1, 1, Vec3(2, -1, 0.5));
  const Vec3 n = Vec3(0.3, -0.8, 0.5).normalized();
  for (double share : {0.01, 0.37, 0.5, 0.99}) {
    const auto s = plane_offset_for_share(mesh, CellId(0), n, share);
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(volume_above_plane(mesh, CellId(0), n, *s), share, 1e-12);
  }
  // An axis-aligned normal: the plane is x = x0 + 1 - share.
  const auto s = plane_offset_for_share(mesh, CellId(0), Vec3(1, 0, 0), 0.37);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, 2.63, 1e-12);
  EXPECT_FALSE(plane_offset_for_share(mesh, CellId(0), n, 0.0).has_value());
  EXPECT_FALSE(plane_offset_for_share(mesh, CellId(0), n, 1.0).has_value());
}

}  // namespace
}  // namespace hexadapt
