// NodeConstraint keeps its normals apart from the node (allocated with the first): a copy
// must own its normals, and a free node's constraint must stay free whatever is copied.
#include "hexadapt/adapt/node_constraint.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace hexadapt {
namespace {

TEST(NodeConstraint, AFreeNodeMovesFreely) {
  const NodeConstraint c;
  EXPECT_EQ(c.n_normals(), 0);
  EXPECT_FALSE(c.fixed(3));
  EXPECT_EQ(c.project(Vec3(1, 2, 3)), Vec3(1, 2, 3));
}

TEST(NodeConstraint, NormalsRemoveTheirComponentsAndThreeFix) {
  NodeConstraint c;
  c.add(Vec3(0, 0, 2));
  c.add(Vec3(0, 0, -1));  // spanned already
  EXPECT_EQ(c.n_normals(), 1);
  EXPECT_EQ(c.project(Vec3(1, 2, 3)), Vec3(1, 2, 0));
  c.add(Vec3(1, 0, 1));  // its part off the first normal
  EXPECT_EQ(c.n_normals(), 2);
  EXPECT_EQ(c.project(Vec3(1, 2, 3)), Vec3(0, 2, 0));
  EXPECT_TRUE(c.fixed(2));
  EXPECT_FALSE(c.fixed(3));
  c.add(Vec3(0, 1, 0));
  EXPECT_TRUE(c.fixed(3));
  EXPECT_EQ(c.project(Vec3(1, 2, 3)), Vec3::Zero());
}

TEST(NodeConstraint, ACopyOwnsItsNormals) {
  NodeConstraint a;
  a.add(Vec3(1, 0, 0));
  NodeConstraint b = a;
  b.add(Vec3(0, 1, 0));
  b.freeze();
  EXPECT_EQ(a.n_normals(), 1);
  EXPECT_FALSE(a.frozen());
  EXPECT_EQ(b.n_normals(), 2);
  EXPECT_EQ(b.normal(0), Vec3(1, 0, 0));

  NodeConstraint c;
  c = b;
  a = a;  // assigned to itself: unchanged
  EXPECT_EQ(a.n_normals(), 1);
  EXPECT_TRUE(c.frozen());
  EXPECT_EQ(c.n_normals(), 2);
  EXPECT_EQ(c.project(Vec3(1, 1, 1)), Vec3::Zero());
  const NodeConstraint free = c.unfrozen();
  EXPECT_EQ(free.project(Vec3(1, 1, 1)), Vec3(0, 0, 1));

  c = NodeConstraint();  // a free one assigned over held normals
  EXPECT_EQ(c.n_normals(), 0);
  EXPECT_EQ(c.project(Vec3(1, 1, 1)), Vec3(1, 1, 1));
}

TEST(NodeConstraint, OneMovedFromIsFree) {
  NodeConstraint a;
  a.add(Vec3(1, 0, 0));
  a.freeze();
  const NodeConstraint b = std::move(a);
  EXPECT_EQ(b.n_normals(), 1);
  EXPECT_TRUE(b.frozen());
  EXPECT_EQ(a.n_normals(), 0);  // NOLINT(bugprone-use-after-move): what is checked
  EXPECT_FALSE(a.frozen());
  EXPECT_EQ(a.project(Vec3(1, 1, 1)), Vec3(1, 1, 1));
  NodeConstraint c;
  c.add(Vec3(0, 1, 0));
  c = std::move(a);
  EXPECT_EQ(c.project(Vec3(1, 1, 1)), Vec3(1, 1, 1));
}

TEST(NodeConstraint, VectorsOfThemCopyAndGrow) {
  std::vector<NodeConstraint> v(3);
  v[1].add(Vec3(0, 0, 1));
  std::vector<NodeConstraint> w = v;
  for (int k = 0; k < 100; ++k) w.push_back(v[1]);  // reallocations move them
  w[1].add(Vec3(1, 0, 0));
  EXPECT_EQ(v[1].n_normals(), 1);
  EXPECT_EQ(w[1].n_normals(), 2);
  EXPECT_EQ(w.back().n_normals(), 1);
  EXPECT_EQ(w[0].n_normals(), 0);
}

}  // namespace
}  // namespace hexadapt
