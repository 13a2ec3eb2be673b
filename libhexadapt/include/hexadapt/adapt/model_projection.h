// Closest points on the geometric model of interface reconstruction (paper sec. 5.3,
// DESIGN 4.2-4.3): the target correction keeps every corrected target on the model, a
// surface node on the facets of its own material pair, a feature-curve node on the model's
// curves.
//
// Facets are bilinear quads (3D); each is split into two triangles along its 0-2 diagonal
// for the closest-point computation (exact for planar facets, which is what Cartesian pixel
// faces are). A uniform bucket grid over the facets' and curves' bounding boxes answers
// queries within a radius without a scan of the whole model: a query visits the buckets
// overlapping balls of growing size, up to the radius, until one holds a facet.
#pragma once

#include <optional>
#include <unordered_map>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/reconstruct/model.h"

namespace hexadapt {

/// Closest point of triangle (a, b, c) to x.
Vec3 closest_point_on_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c);
/// Closest point of segment (a, b) to x.
Vec3 closest_point_on_segment(const Vec3& x, const Vec3& a, const Vec3& b);

class ModelProjection {
 public:
  /// Indexes the model's 3D facets and curves in buckets of `bucket_size` (> 0; about the
  /// facet size or a little more; queries search balls growing from it). Throws
  /// OptionError for a 2D model or a bad size.
  ModelProjection(const reconstruct::InterfaceModel& model, double bucket_size);

  /// The closest point to x on the facets of the material pair {lo, hi} (any order) within
  /// `radius`; nothing when no such facet is that close.
  std::optional<Vec3> on_surface(const Vec3& x, int lo, int hi, double radius) const;
  /// The closest point to x on the feature curves within `radius`, or nothing.
  std::optional<Vec3> on_curve(const Vec3& x, double radius) const;

 private:
  struct Grid {
    std::unordered_map<long long, std::vector<index_t>> buckets;
  };
  long long key(long long i, long long j, long long k) const;
  std::array<long long, 3> bucket_of(const Vec3& x) const;
  void insert(Grid& grid, index_t item, const Vec3& lo, const Vec3& hi);
  template <class Distance>
  std::optional<Vec3> nearest(const Grid& grid, const Vec3& x, double radius,
                              const Distance& closest) const;
  template <class Distance>
  std::optional<Vec3> nearest_within(const Grid& grid, const Vec3& x, double radius,
                                     const Distance& closest) const;

  const reconstruct::InterfaceModel& model_;
  double size_;
  Vec3 origin_;
  Grid facets_, curves_;
};

}  // namespace hexadapt
