#include "hexadapt/adapt/model_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"

namespace hexadapt {

Vec3 closest_point_on_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double len2 = d.squaredNorm();
  if (!(len2 > 0)) return a;
  const double t = std::clamp((x - a).dot(d) / len2, 0.0, 1.0);
  return a + t * d;
}

// Voronoi regions of the triangle: a vertex, an edge, or the inside (Ericson, Real-Time
// Collision Detection, sec. 5.1.5, rewritten).
Vec3 closest_point_on_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ax = x - a;
  const double d1 = ab.dot(ax), d2 = ac.dot(ax);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bx = x - b;
  const double d3 = ab.dot(bx), d4 = ac.dot(bx);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cx = x - c;
  const double d5 = ab.dot(cx), d6 = ac.dot(cx);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double sum = va + vb + vc;
  if (!(std::abs(sum) > 0)) return closest_point_on_segment(x, a, b);  // degenerate triangle
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

namespace {

constexpr long long bucket_span = 1LL << 20;
constexpr long long bucket_offset = 1LL << 19;

}  // namespace

ModelProjection::ModelProjection(const reconstruct::InterfaceModel& model, double bucket_size)
    : model_(model), size_(bucket_size), origin_(Vec3::Zero()) {
  if (model.dim != 3) throw OptionError("model projection needs a 3D model");
  if (!(bucket_size > 0) || !std::isfinite(bucket_size))
    throw OptionError("model projection: bucket size must be > 0");
  if (!model.points.empty()) {
    origin_ = model.points.front();
    for (const Vec3& p : model.points) origin_ = origin_.cwiseMin(p);
  }
  const auto& P = model.points;
  for (std::size_t f = 0; f < model.facets.size(); ++f) {
    Vec3 lo = P[static_cast<std::size_t>(model.facets[f][0])], hi = lo;
    for (index_t v : model.facets[f]) {
      lo = lo.cwiseMin(P[static_cast<std::size_t>(v)]);
      hi = hi.cwiseMax(P[static_cast<std::size_t>(v)]);
    }
    insert(facets_, static_cast<index_t>(f), lo, hi);
  }
  for (std::size_t e = 0; e < model.curves.size(); ++e) {
    const Vec3& a = P[static_cast<std::size_t>(model.curves[e][0])];
    const Vec3& b = P[static_cast<std::size_t>(model.curves[e][1])];
    insert(curves_, static_cast<index_t>(e), a.cwiseMin(b), a.cwiseMax(b));
  }
}

long long ModelProjection::key(long long i, long long j, long long k) const {
  return ((i + bucket_offset) * bucket_span + (j + bucket_offset)) * bucket_span +
         (k + bucket_offset);
}

std::array<long long, 3> ModelProjection::bucket_of(const Vec3& x) const {
  std::array<long long, 3> b{};
  for (int a = 0; a < 3; ++a) {
    const double u = std::floor((x[a] - origin_[a]) / size_);
    b[static_cast<std::size_t>(a)] = static_cast<long long>(
        std::clamp(u, static_cast<double>(-bucket_offset + 1), static_cast<double>(bucket_offset - 1)));
  }
  return b;
}

void ModelProjection::insert(Grid& grid, index_t item, const Vec3& lo, const Vec3& hi) {
  const auto a = bucket_of(lo), b = bucket_of(hi);
  for (long long i = a[0]; i <= b[0]; ++i)
    for (long long j = a[1]; j <= b[1]; ++j)
      for (long long k = a[2]; k <= b[2]; ++k) grid.buckets[key(i, j, k)].push_back(item);
}

// Items are visited bucket by bucket; ties go to the lowest item id so the answer does not
// depend on the visiting order.
template <class Distance>
std::optional<Vec3> ModelProjection::nearest(const Grid& grid, const Vec3& x, double radius,
                                             const Distance& closest) const {
  // Growing balls: a point found within one is the nearest, and most queries (targets
  // already near the model) end in the first, small one.
  for (double r = std::min(size_, radius);; r = std::min(2 * r, radius)) {
    if (auto p = nearest_within(grid, x, r, closest)) return p;
    if (r >= radius) return std::nullopt;
  }
}

template <class Distance>
std::optional<Vec3> ModelProjection::nearest_within(const Grid& grid, const Vec3& x,
                                                    double radius,
                                                    const Distance& closest) const {
  const Vec3 r = Vec3::Constant(radius);
  const auto a = bucket_of(x - r), b = bucket_of(x + r);
  double best = radius * radius;
  index_t best_item = std::numeric_limits<index_t>::max();
  std::optional<Vec3> out;
  for (long long i = a[0]; i <= b[0]; ++i)
    for (long long j = a[1]; j <= b[1]; ++j)
      for (long long k = a[2]; k <= b[2]; ++k) {
        const auto it = grid.buckets.find(key(i, j, k));
        if (it == grid.buckets.end()) continue;
        for (index_t item : it->second) {
          const std::optional<Vec3> p = closest(item);
          if (!p) continue;
          const double d = (*p - x).squaredNorm();
          if (d < best || (d == best && item < best_item && out)) {
            best = d;
            best_item = item;
            out = p;
          }
        }
      }
  return out;
}

std::optional<Vec3> ModelProjection::on_surface(const Vec3& x, int lo, int hi,
                                                double radius) const {
  if (lo > hi) std::swap(lo, hi);
  const auto& P = model_.points;
  return nearest(facets_, x, radius, [&](index_t f) -> std::optional<Vec3> {
    const auto fi = static_cast<std::size_t>(f);
    if (model_.facet_materials[fi][0] != lo || model_.facet_materials[fi][1] != hi)
      return std::nullopt;
    const auto& q = model_.facets[fi];
    auto p = [&](int k) { return P[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])]; };
    const Vec3 s = closest_point_on_triangle(x, p(0), p(1), p(2));
    const Vec3 t = closest_point_on_triangle(x, p(0), p(2), p(3));
    return (s - x).squaredNorm() <= (t - x).squaredNorm() ? s : t;
  });
}

std::optional<Vec3> ModelProjection::on_curve(const Vec3& x, double radius) const {
  const auto& P = model_.points;
  return nearest(curves_, x, radius, [&](index_t e) -> std::optional<Vec3> {
    const auto& c = model_.curves[static_cast<std::size_t>(e)];
    return closest_point_on_segment(x, P[static_cast<std::size_t>(c[0])],
                                    P[static_cast<std::size_t>(c[1])]);
  });
}

}  // namespace hexadapt
