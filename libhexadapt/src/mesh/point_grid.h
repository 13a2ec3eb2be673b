// A uniform grid over a set of points for neighbourhood queries in linear time: the points
// are sorted by bucket (k, j, i), so the points of a row of buckets are one contiguous range
// found by binary search. Used by the mesh check (duplicates, hanging nodes).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/geometry.h"

namespace hexadapt {

class PointGrid {
 public:
  /// Indexes points[ids[i]] with buckets of size h (> 0). Points with a NaN or infinite
  /// coordinate are left out.
  PointGrid(const std::vector<Vec3>& points, std::vector<NodeId> ids, double h);

  /// The ids of the indexed points inside the box [lo, hi], in increasing id.
  std::vector<NodeId> in_box(const Vec3& lo, const Vec3& hi) const;

 private:
  using Key = std::array<std::int64_t, 3>;  // (k, j, i): rows of constant (k, j) are contiguous
  bool key_of(const Vec3& p, Key& key) const;

  const std::vector<Vec3>& points_;
  Vec3 origin_ = Vec3::Zero();
  double h_ = 1;
  std::vector<Key> keys_;    // sorted
  std::vector<NodeId> ids_;  // in the order of keys_
};

/// Bounding box of points (min, max); (0, 0) when empty. NaN coordinates are ignored.
std::array<Vec3, 2> bounding_box(const std::vector<Vec3>& points);

}  // namespace hexadapt
