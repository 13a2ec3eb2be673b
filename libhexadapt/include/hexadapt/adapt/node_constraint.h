// How far a node may move: the planes it must stay on (domain boundary, material interface).
//
// A constraint is a set of up to three orthonormal normals; an allowed displacement has no
// component along any of them. No normal: free; one: slides on a plane (2D: on a line, since
// 2D points keep their z); two in 3D: slides along a line (a box edge, a triple curve);
// `dim` normals: fixed. The domain boundary is found from the kernel (faces with no cell
// across), never from a bounding box, so jittered and unstructured grids work (paper sec. 5,
// DESIGN 4.3: "domain-boundary nodes stay on the boundary").
#pragma once

#include <array>

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt {

class NodeConstraint {
 public:
  int n_normals() const { return n_; }
  const Vec3& normal(int k) const { return normals_[static_cast<std::size_t>(k)]; }
  /// True when every displacement is forbidden in a `dim`-dimensional mesh.
  bool fixed(int dim) const { return n_ >= dim; }
  /// Adds the direction unless it is (nearly) spanned by the normals already held.
  void add(const Vec3& direction);
  /// Adds every normal of `other`.
  void add(const NodeConstraint& other);
  /// The displacement with its components along the normals removed.
  Vec3 project(const Vec3& displacement) const;

 private:
  std::array<Vec3, 3> normals_;
  int n_ = 0;
};

struct BoundaryOptions {
  /// Two boundary faces at a node whose normals differ by more than this angle (degrees)
  /// make a feature: the node keeps to the edge (or corner) between them.
  double feature_angle = 35.0;
};

/// The boundary constraint of every node: free inside, on its plane on a boundary face, on
/// the edge line on a feature edge, fixed at a corner.
template <class M>
IdVector<NodeId, NodeConstraint> boundary_constraints(const M& mesh,
                                                      const BoundaryOptions& options = {});

}  // namespace hexadapt
