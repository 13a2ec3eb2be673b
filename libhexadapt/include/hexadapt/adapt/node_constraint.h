// How far a node may move: the planes it must stay on (domain boundary, material interface).
//
// A constraint is a set of up to three orthonormal normals; an allowed displacement has no
// component along any of them. No normal: free; one: slides on a plane (2D: on a line, since
// 2D points keep their z); two in 3D: slides along a line (a box edge, a triple curve);
// `dim` normals: fixed. A frozen node is fixed whatever its normals, which still say where it
// lies (a rank border on its plane, an interface). The domain boundary is found from the kernel
// (faces with no cell across), never from a bounding box, so jittered and unstructured grids work
// (paper sec. 5, DESIGN 4.3: "domain-boundary nodes stay on the boundary").
#pragma once

#include <cstdint>
#include <memory>
#include <utility>

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt {

/// Sixteen bytes for a free node: the normals live apart, allocated with the first one (most
/// nodes of a grid are free, and a pipeline holds several constraints per node).
class NodeConstraint {
 public:
  NodeConstraint() = default;
  NodeConstraint(const NodeConstraint& other);
  NodeConstraint& operator=(const NodeConstraint& other);
  /// A constraint moved from is free.
  NodeConstraint(NodeConstraint&& other) noexcept
      : normals_(std::move(other.normals_)),
        n_(std::exchange(other.n_, 0)),
        frozen_(std::exchange(other.frozen_, false)) {}
  NodeConstraint& operator=(NodeConstraint&& other) noexcept {
    normals_ = std::move(other.normals_);
    n_ = std::exchange(other.n_, 0);
    frozen_ = std::exchange(other.frozen_, false);
    return *this;
  }
  ~NodeConstraint() = default;

  int n_normals() const { return n_; }
  const Vec3& normal(int k) const { return normals_[static_cast<std::size_t>(k)]; }
  /// True when every displacement is forbidden in a `dim`-dimensional mesh.
  bool fixed(int dim) const { return frozen_ || n_ >= dim; }
  /// Forbids every displacement, the normals kept.
  void freeze() { frozen_ = true; }
  bool frozen() const { return frozen_; }
  /// The same normals, not frozen: where a frozen node may move once let go.
  NodeConstraint unfrozen() const {
    NodeConstraint out;
    for (int k = 0; k < n_; ++k) out.add(normal(k));
    return out;
  }
  /// Adds the direction unless it is (nearly) spanned by the normals already held.
  void add(const Vec3& direction);
  /// Adds every normal of `other`, frozen when it is.
  void add(const NodeConstraint& other);
  /// The displacement with its components along the normals removed (zero when frozen).
  Vec3 project(const Vec3& displacement) const;

 private:
  std::unique_ptr<Vec3[]> normals_;  // three places once a normal is added
  std::int8_t n_ = 0;
  bool frozen_ = false;
};

struct BoundaryOptions {
  /// Two boundary faces at a node whose normals differ by more than this angle (degrees)
  /// make a feature: the node keeps to the edge (or corner) between them.
  double feature_angle = 35.0;
  /// The input nodes that never move (1), by input node id; empty: none. A part of a grid
  /// adapted on its own, as one rank's, freezes the nodes it shares with the other parts, so
  /// that the parts' faces there stay the input's and the parts fit together. The cells around
  /// a frozen node are never pillowed (guaranteed method only), unless pillow_frozen.
  IdVector<NodeId, char> frozen;
  /// Pillow the cells around the frozen nodes as the others (interface_pillow.h): a frozen
  /// node's copies start where a free node's would (pillow.h), are smoothed among themselves
  /// with every other node held, then frozen there. Two parts of a grid holding the cells
  /// around the frozen nodes lay the same layers across them, unless a run of the mending
  /// (AdaptOptions::mend_rounds) leaves out cells near them on one part only; the copies'
  /// places depend on the nodes the smoothing of the layers laid before moved, which the
  /// cells beyond sway: the same to the bit on the asteroid and the Venn case at 20^3 cut
  /// with three layers beyond, up to 1.8e-4 apart in a grid of 1 on the asteroid at 48^3.
  bool pillow_frozen = false;

  /// The same options without frozen nodes (for a patch of the mesh with its own node ids).
  BoundaryOptions without_frozen() const {
    BoundaryOptions out;
    out.feature_angle = feature_angle;
    return out;
  }
  bool is_frozen(NodeId v) const { return v.idx() < frozen.size() && frozen[v] != 0; }
  /// The same options on a mesh whose node v is a copy of input node origin[v] (a pillowed
  /// mesh): with pillow_frozen, the copies of frozen nodes are frozen too.
  BoundaryOptions on_copies(const IdVector<NodeId, NodeId>& origin) const;
};

/// The boundary constraint of every node: free inside, on its plane on a boundary face, on
/// the edge line on a feature edge, fixed at a corner; options.frozen nodes frozen.
template <class M>
IdVector<NodeId, NodeConstraint> boundary_constraints(const M& mesh,
                                                      const BoundaryOptions& options = {});

}  // namespace hexadapt
