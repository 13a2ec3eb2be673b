#include "hexadapt/adapt/node_constraint.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {
// A direction closer than this (sine of the angle) to the span of the normals already held
// adds nothing: an interface that runs along the boundary must not pin its nodes.
constexpr double span_tolerance = 0.05;
}  // namespace

NodeConstraint::NodeConstraint(const NodeConstraint& other)
    : normals_(other.normals_ ? std::make_unique<Vec3[]>(3) : nullptr),
      n_(other.n_),
      frozen_(other.frozen_) {
  if (normals_) std::copy(other.normals_.get(), other.normals_.get() + n_, normals_.get());
}

NodeConstraint& NodeConstraint::operator=(const NodeConstraint& other) {
  if (this != &other) *this = NodeConstraint(other);
  return *this;
}

void NodeConstraint::add(const Vec3& direction) {
  if (n_ >= 3) return;
  Vec3 d = direction;
  const double len0 = d.norm();
  if (!(len0 > 0)) return;
  d /= len0;
  for (int k = 0; k < n_; ++k) d -= d.dot(normal(k)) * normal(k);
  const double len = d.norm();
  if (len < span_tolerance) return;
  if (!normals_) normals_ = std::make_unique<Vec3[]>(3);
  normals_[static_cast<std::size_t>(n_++)] = d / len;
}

void NodeConstraint::add(const NodeConstraint& other) {
  for (int k = 0; k < other.n_normals(); ++k) add(other.normal(k));
  frozen_ = frozen_ || other.frozen_;
}

Vec3 NodeConstraint::project(const Vec3& displacement) const {
  if (frozen_) return Vec3::Zero();
  Vec3 d = displacement;
  for (int k = 0; k < n_; ++k) d -= d.dot(normal(k)) * normal(k);
  return d;
}

template <class M>
IdVector<NodeId, NodeConstraint> boundary_constraints(const M& mesh,
                                                      const BoundaryOptions& options) {
  if (!(options.feature_angle > 0 && options.feature_angle < 90))
    throw OptionError("feature angle must be in (0, 90) degrees, got " +
                      std::to_string(options.feature_angle));
  const double cos_feature = std::cos(options.feature_angle * M_PI / 180.0);
  // Per node, clusters of boundary-face normals (sum of the normals in each cluster).
  IdVector<NodeId, std::vector<Vec3>> clusters(static_cast<std::size_t>(mesh.n_nodes()));
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      if (mesh.neighbour(c, lf).valid()) continue;
      const Vec3 n = face_normal(mesh, c, lf);
      for (NodeId v : mesh.face_nodes(c, lf)) {
        auto& list = clusters[v];
        bool merged = false;
        for (Vec3& s : list)
          if (s.normalized().dot(n) >= cos_feature) {
            s += n;
            merged = true;
            break;
          }
        if (!merged) list.push_back(n);
      }
    }
  IdVector<NodeId, NodeConstraint> out(static_cast<std::size_t>(mesh.n_nodes()));
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    for (const Vec3& s : clusters[v]) out[v].add(s);
    if (options.is_frozen(v)) out[v].freeze();
  }
  return out;
}

BoundaryOptions BoundaryOptions::on_copies(const IdVector<NodeId, NodeId>& origin) const {
  if (!pillow_frozen || frozen.empty()) return *this;
  BoundaryOptions out = *this;
  out.frozen.assign(origin.size(), 0);
  for (NodeId v : id_range<NodeId>(static_cast<index_t>(origin.size())))
    out.frozen[v] = is_frozen(origin[v]);
  return out;
}

template IdVector<NodeId, NodeConstraint> boundary_constraints<QuadMesh>(const QuadMesh&,
                                                                         const BoundaryOptions&);
template IdVector<NodeId, NodeConstraint> boundary_constraints<HexMesh>(const HexMesh&,
                                                                        const BoundaryOptions&);

}  // namespace hexadapt
