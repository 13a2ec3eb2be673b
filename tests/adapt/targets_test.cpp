#include "hexadapt/adapt/targets.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"
#include "hexadapt/core/error.h"

namespace hexadapt {
namespace {

using test::majority;
using test::sample_fractions;

template <class M>
Targets targets_of(const M& mesh, const Fractions& f) {
  return compute_targets(mesh, f, majority(f), boundary_constraints(mesh));
}

// Fractions of the half-space x < a computed exactly for unit cells.
template <class M>
Fractions layer_fractions(const M& mesh, double a) {
  Fractions f(mesh.n_cells(), {"left", "right"});
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const double x0 = mesh.point(mesh.cell_nodes(c)[0]).x();
    const double left = std::clamp(a - x0, 0.0, 1.0);
    f(c, 0) = left;
    f(c, 1) = 1 - left;
  }
  return f;
}

TEST(Targets, StraightInterfaceThroughCellCentresIsExact2D) {
  const QuadMesh mesh = make_quad_grid(8, 5);
  const Targets t = targets_of(mesh, layer_fractions(mesh, 3.5));
  EXPECT_EQ(t.n_interface_nodes, 6);  // the node column x = 4
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!t.has[n]) continue;
    EXPECT_NEAR(t.position[n].x(), 3.5, 1e-9);
    EXPECT_NEAR(t.position[n].y(), mesh.point(n).y(), 1e-9);  // boundary nodes stay on it
  }
}

TEST(Targets, StraightInterfaceThroughCellCentresIsExact3D) {
  const HexMesh mesh = make_hex_grid(6, 3, 4);
  const Targets t = targets_of(mesh, layer_fractions(mesh, 2.5));
  EXPECT_EQ(t.n_interface_nodes, 4 * 5);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!t.has[n]) continue;
    EXPECT_NEAR(t.position[n].x(), 2.5, 1e-9);
    EXPECT_NEAR(t.position[n].y(), mesh.point(n).y(), 1e-9);
    EXPECT_NEAR(t.position[n].z(), mesh.point(n).z(), 1e-9);
  }
}

// The volume-consistent crossing puts the plane exactly where the fractions say, whatever
// the offset of the interface inside its cells (and on the faces when it lies on them);
// boundary cells see mirrored neighbours, so their normals do not tilt either.
template <class M>
void expect_targets_on_plane(const M& mesh, double a) {
  const Targets t = targets_of(mesh, layer_fractions(mesh, a));
  ASSERT_GT(t.n_interface_nodes, 0);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!t.has[n]) continue;
    const Vec3 p = mesh.point(n), q = t.position[n];
    EXPECT_NEAR(q.x(), a, 1e-9) << "a = " << a << " node " << p.transpose();
    EXPECT_NEAR(q.y(), p.y(), 1e-9) << "a = " << a;
    EXPECT_NEAR(q.z(), p.z(), 1e-9) << "a = " << a;
  }
}

TEST(Targets, StraightInterfaceAtAnyOffsetIsExact2D) {
  const QuadMesh mesh = make_quad_grid(8, 5);
  for (double a : {3.0, 3.1, 3.37, 3.5, 3.83, 4.9}) expect_targets_on_plane(mesh, a);
}

TEST(Targets, StraightInterfaceAtAnyOffsetIsExact3D) {
  const HexMesh mesh = make_hex_grid(7, 5, 4);
  for (double a : {3.0, 3.1, 3.37, 3.5, 3.83, 4.9}) expect_targets_on_plane(mesh, a);
}

TEST(Targets, DiskTargetsLieCloseToTheCircle) {
  const Vec3 centre(6.1, 5.9, 0);
  const double r = 3.7;
  const QuadMesh mesh = make_quad_grid(12, 12);
  const auto f = sample_fractions(
      mesh, [&](const Vec3& p) { return (p - centre).norm() < r; }, 2);
  const Targets t = targets_of(mesh, f);
  ASSERT_GT(t.n_interface_nodes, 20);
  double worst = 0;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (t.has[n]) worst = std::max(worst, std::abs((t.position[n] - centre).norm() - r));
  EXPECT_LT(worst, 0.06);  // measured 0.038
}

// The targets follow the grid's unit: the same disk on a grid in units 1e20 times larger or
// smaller gets the same targets, scaled (the fraction gradients are per unit length, and a
// flat gradient is judged by the fraction change across a cell, not by its size).
TEST(Targets, TheSameInAnyUnit) {
  const Vec3 centre(6.1, 5.9, 0);
  const QuadMesh unit = make_quad_grid(12, 12);
  const auto f = sample_fractions(
      unit, [&](const Vec3& p) { return (p - centre).norm() < 3.7; }, 2);
  const Targets t = targets_of(unit, f);
  for (double scale : {1e-6, 1e6, 1e20}) {
    const QuadMesh scaled = make_quad_grid(12, 12, Vec3::Zero(), Vec3(scale, scale, 1));
    const Targets s = targets_of(scaled, f);
    ASSERT_EQ(s.faces.size(), t.faces.size());
    for (std::size_t i = 0; i < t.faces.size(); ++i)
      EXPECT_NEAR((t.faces[i].normal - s.faces[i].normal).norm(), 0, 1e-12) << scale;
    for (NodeId n : id_range<NodeId>(unit.n_nodes()))
      EXPECT_NEAR((s.position[n] / scale - t.position[n]).norm(), 0, 1e-12) << scale;
  }
}

TEST(Targets, SphereTargetsLieCloseToTheSphere) {
  const Vec3 centre(4.1, 3.9, 4.05);
  const double r = 2.6;
  const HexMesh mesh = make_hex_grid(8, 8, 8);
  const auto f = sample_fractions(
      mesh, [&](const Vec3& p) { return (p - centre).norm() < r; }, 2, 8);
  const Targets t = targets_of(mesh, f);
  double worst = 0;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes()))
    if (t.has[n]) worst = std::max(worst, std::abs((t.position[n] - centre).norm() - r));
  EXPECT_LT(worst, 0.15);  // measured 0.106
}

TEST(Targets, NodesOnABoxEdgeSlideAlongIt) {
  // A plane x + y = const crossing the z-edges of the box: targets of the nodes on the
  // edge x = 0 or y = 0 keep both coordinates that pin them there.
  const HexMesh mesh = make_hex_grid(6, 6, 2);
  const auto f = sample_fractions(
      mesh, [](const Vec3& p) { return p.x() + 0.8 * p.y() < 4.3; }, 2, 8);
  const Targets t = targets_of(mesh, f);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!t.has[n]) continue;
    const Vec3 p = mesh.point(n), q = t.position[n];
    for (int a = 0; a < 3; ++a)
      if (p[a] == 0 || p[a] == 6 || (a == 2 && p[a] == 2)) {
        EXPECT_NEAR(q[a], p[a], 1e-12);
      }
  }
}

TEST(Targets, RejectsMaterialsOutOfRange) {
  const QuadMesh mesh = make_quad_grid(2, 2);
  const Fractions f = layer_fractions(mesh, 1.0);
  IdVector<CellId, int> bad(4, 0);
  bad[CellId(3)] = 2;
  EXPECT_THROW(compute_targets(mesh, f, bad, boundary_constraints(mesh)), InputError);
}

}  // namespace
}  // namespace hexadapt

namespace hexadapt {
namespace {

TEST(Targets, SlidingConstraintsFollowTheInterfaceAndTheBoundary) {
  const QuadMesh mesh = make_quad_grid(8, 5);
  Fractions f(mesh.n_cells(), {"left", "right"});
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const double left = std::clamp(3.5 - mesh.point(mesh.cell_nodes(c)[0]).x(), 0.0, 1.0);
    f(c, 0) = left;
    f(c, 1) = 1 - left;
  }
  const auto boundary = boundary_constraints(mesh);
  const Targets t = compute_targets(mesh, f, test::majority(f), boundary);
  const auto slide = sliding_constraints(boundary, t);
  const NodeId inner(4 + 9 * 2), on_boundary(4), corner(0), plain(1 + 9 * 2);
  EXPECT_EQ(slide[inner].n_normals(), 1);
  EXPECT_NEAR(std::abs(slide[inner].normal(0).x()), 1.0, 1e-9);
  EXPECT_EQ(slide[inner].project(Vec3(1, 1, 0)), Vec3(0, 1, 0));
  EXPECT_TRUE(slide[on_boundary].fixed(2));  // on the interface and on the boundary line
  EXPECT_TRUE(slide[corner].fixed(2));
  EXPECT_EQ(slide[plain].n_normals(), 0);
}

}  // namespace
}  // namespace hexadapt
