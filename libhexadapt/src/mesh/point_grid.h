// A uniform grid over a set of points for neighbourhood queries in linear time: the points
// are sorted by bucket (k, j, i), so the points of a row of buckets are one contiguous range
// found by binary search. Used by the mesh check (duplicates, hanging nodes).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"

namespace hexadapt {

class PointGrid {
 public:
  /// Indexes points[ids[i]] with buckets of size h (> 0). Points with a NaN or infinite
  /// coordinate are left out.
  PointGrid(const std::vector<Vec3>& points, std::vector<NodeId> ids, double h);

  /// The ids of the indexed points inside the box [lo, hi], in increasing id.
  std::vector<NodeId> in_box(const Vec3& lo, const Vec3& hi) const;

  /// Calls f(id) for every indexed point inside the box [lo, hi], in no particular order.
  template <class F>
  void for_each_in_box(const Vec3& lo, const Vec3& hi, F&& f) const {
    auto inside = [&](NodeId n) {
      const Vec3& p = points_[n.idx()];
      return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    };
    Key a, b;
    if (!rows_of(lo, hi, a, b)) {
      // A box spanning more rows of buckets than there are points: scan them all.
      for (NodeId n : ids_)
        if (inside(n)) f(n);
      return;
    }
    for (std::int64_t k = a[0]; k <= b[0]; ++k)
      for (std::int64_t j = a[1]; j <= b[1]; ++j) {
        const auto [first, last] = row(k, j, a[2], b[2]);
        for (std::size_t i = first; i < last; ++i)
          if (inside(ids_[i])) f(ids_[i]);
      }
  }

 private:
  using Key = std::array<std::int64_t, 3>;  // (k, j, i): rows of constant (k, j) are contiguous
  bool key_of(const Vec3& p, Key& key) const;
  /// Keys of the corners of the box; false when a row-by-row search would not pay off.
  bool rows_of(const Vec3& lo, const Vec3& hi, Key& a, Key& b) const;
  /// The index range of the points in buckets (i0..i1, j, k).
  std::pair<std::size_t, std::size_t> row(std::int64_t k, std::int64_t j, std::int64_t i0,
                                          std::int64_t i1) const;

  const std::vector<Vec3>& points_;
  Vec3 origin_ = Vec3::Zero();
  double h_ = 1;
  std::vector<Key> keys_;    // sorted
  std::vector<NodeId> ids_;  // in the order of keys_
  struct RowHash {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& r) const noexcept {
      return std::hash<std::int64_t>()(r.first * 0x9E3779B97F4A7C15LL ^ r.second);
    }
  };
  // (k, j) -> the index range of that row in keys_: rows are found in O(1), not by a search
  // over all points.
  std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::pair<std::size_t, std::size_t>,
                     RowHash>
      rows_;
};

/// Bounding box of points (min, max); (0, 0) when empty. NaN coordinates are ignored.
std::array<Vec3, 2> bounding_box(const std::vector<Vec3>& points);

}  // namespace hexadapt
