#include "point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace hexadapt {

namespace {
// Beyond this many buckets per axis the keys could overflow: scan all points instead.
constexpr double kMaxBuckets = 1e18;
}  // namespace

std::array<Vec3, 2> bounding_box(const std::vector<Vec3>& points) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()),
       hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  for (const Vec3& p : points) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!(lo.x() <= hi.x())) return {Vec3::Zero(), Vec3::Zero()};
  return {lo, hi};
}

PointGrid::PointGrid(const std::vector<Vec3>& points, std::vector<NodeId> ids, double h)
    : points_(points), h_(h > 0 && std::isfinite(h) ? h : 1.0) {
  std::vector<Vec3> subset;
  subset.reserve(ids.size());
  for (NodeId n : ids) subset.push_back(points[n.idx()]);
  const auto box = bounding_box(subset);
  origin_ = box[0];
  // Buckets far below the rounding of the coordinates would only overflow the keys.
  h_ = std::max(h_, 1e-15 * (box[1] - box[0]).lpNorm<Eigen::Infinity>());
  std::vector<std::pair<Key, NodeId>> entries;
  entries.reserve(ids.size());
  for (NodeId n : ids) {
    Key k;
    if (key_of(points[n.idx()], k)) entries.emplace_back(k, n);
  }
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second < b.second;
  });
  keys_.reserve(entries.size());
  ids_.reserve(entries.size());
  for (const auto& [k, n] : entries) {
    keys_.push_back(k);
    ids_.push_back(n);
  }
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    auto& range = rows_[{keys_[i][0], keys_[i][1]}];
    if (range.second == 0) range.first = i;
    range.second = i + 1;
  }
}

bool PointGrid::key_of(const Vec3& p, Key& key) const {
  if (!p.allFinite()) return false;
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor((p[a] - origin_[a]) / h_);
    if (!(std::abs(f) < kMaxBuckets)) return false;
    key[static_cast<std::size_t>(2 - a)] = static_cast<std::int64_t>(f);
  }
  return true;
}

bool PointGrid::rows_of(const Vec3& lo, const Vec3& hi, Key& a, Key& b) const {
  if (!key_of(lo, a) || !key_of(hi, b)) return false;
  const double rows = double(b[0] - a[0] + 1) * double(b[1] - a[1] + 1);
  return rows < double(ids_.size()) + 1;
}

std::pair<std::size_t, std::size_t> PointGrid::row(std::int64_t k, std::int64_t j, std::int64_t i0,
                                                   std::int64_t i1) const {
  const auto it = rows_.find({k, j});
  if (it == rows_.end()) return {0, 0};
  const auto begin = keys_.begin() + static_cast<std::ptrdiff_t>(it->second.first);
  const auto end = keys_.begin() + static_cast<std::ptrdiff_t>(it->second.second);
  const auto first = std::lower_bound(begin, end, Key{k, j, i0});
  const auto last = std::upper_bound(first, end, Key{k, j, i1});
  return {static_cast<std::size_t>(first - keys_.begin()),
          static_cast<std::size_t>(last - keys_.begin())};
}

std::vector<NodeId> PointGrid::in_box(const Vec3& lo, const Vec3& hi) const {
  std::vector<NodeId> out;
  for_each_in_box(lo, hi, [&](NodeId n) { out.push_back(n); });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hexadapt
