#include "slice.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hexadapt::render {
namespace {

const Vec3& node(const io::MeshData& d, index_t cell, int k) {
  const auto i = static_cast<std::size_t>(cell) * static_cast<std::size_t>(d.nodes_per_cell()) +
                 static_cast<std::size_t>(k);
  return d.points[d.cells[i].idx()];
}

// Orders the points of a convex cut by angle around their mean.
void order_around_centre(std::vector<Point2>& p) {
  double cx = 0, cy = 0;
  for (const auto& q : p) cx += q[0], cy += q[1];
  cx /= static_cast<double>(p.size());
  cy /= static_cast<double>(p.size());
  std::sort(p.begin(), p.end(), [&](const Point2& a, const Point2& b) {
    return std::atan2(a[1] - cy, a[0] - cx) < std::atan2(b[1] - cy, b[0] - cx);
  });
}

void drop_duplicates(std::vector<Point2>& p, double tolerance) {
  std::vector<Point2> kept;
  for (const auto& q : p) {
    const bool seen = std::any_of(kept.begin(), kept.end(), [&](const Point2& k) {
      return std::abs(k[0] - q[0]) <= tolerance && std::abs(k[1] - q[1]) <= tolerance;
    });
    if (!seen) kept.push_back(q);
  }
  p.swap(kept);
}

// The 12 edges of a hex in binary lattice order join nodes differing in one bit.
std::vector<Point2> cut_hex(const io::MeshData& d, index_t cell, double z) {
  std::vector<Point2> cut;
  double extent = 0;
  for (int a = 0; a < 8; ++a) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (a & bit) continue;
      const Vec3& p = node(d, cell, a);
      const Vec3& q = node(d, cell, a | bit);
      extent = std::max(extent, (q - p).norm());
      const double lo = std::min(p.z(), q.z()), hi = std::max(p.z(), q.z());
      if (z < lo || z > hi) continue;
      if (hi == lo) {  // the edge lies in the plane
        cut.push_back({p.x(), p.y()});
        cut.push_back({q.x(), q.y()});
        continue;
      }
      const double t = (z - p.z()) / (q.z() - p.z());
      const Vec3 r = p + t * (q - p);
      cut.push_back({r.x(), r.y()});
    }
  }
  drop_duplicates(cut, 1e-12 * extent);
  if (cut.size() >= 3) order_around_centre(cut);
  return cut;
}

std::pair<double, double> z_range(const io::MeshData& d, index_t cell) {
  double lo = node(d, cell, 0).z(), hi = lo;
  for (int k = 1; k < 8; ++k) {
    lo = std::min(lo, node(d, cell, k).z());
    hi = std::max(hi, node(d, cell, k).z());
  }
  return {lo, hi};
}

}  // namespace

std::vector<Polygon> slice_cells(const io::MeshData& data, const SliceOptions& options) {
  std::vector<Polygon> out;
  for (index_t c = 0; c < data.n_cells(); ++c) {
    Polygon poly;
    poly.cell = c;
    if (data.dim == 2) {
      for (int k = 0; k < 4; ++k) poly.points.push_back({node(data, c, k).x(), node(data, c, k).y()});
    } else {
      const auto [lo, hi] = z_range(data, c);
      if (options.z < lo || options.z >= hi) continue;
      poly.points = cut_hex(data, c, options.z);
      if (poly.points.size() < 3) continue;
    }
    out.push_back(std::move(poly));
  }
  return out;
}

std::vector<Arrow> target_arrows(const io::MeshData& data, const std::vector<Polygon>& polygons,
                                 const SliceOptions& options) {
  const io::DataArray* target = data.find_point_array("target");
  if (!target || target->n_components != 3) return {};
  std::vector<char> drawn(data.points.size(), 0);
  std::vector<Arrow> arrows;
  const int npc = data.nodes_per_cell();
  for (const Polygon& poly : polygons) {
    double half_height = 0;
    if (data.dim == 3) {
      const auto [lo, hi] = z_range(data, poly.cell);
      half_height = 0.5 * (hi - lo);
    }
    for (int k = 0; k < npc; ++k) {
      const std::size_t v =
          data.cells[static_cast<std::size_t>(poly.cell) * static_cast<std::size_t>(npc) +
                     static_cast<std::size_t>(k)]
              .idx();
      if (drawn[v]) continue;
      const Vec3& p = data.points[v];
      if (data.dim == 3 && std::abs(p.z() - options.z) > half_height) continue;
      drawn[v] = 1;
      const Point2 to{target->values[3 * v], target->values[3 * v + 1]};
      if (to[0] == p.x() && to[1] == p.y()) continue;
      arrows.push_back({{p.x(), p.y()}, to});
    }
  }
  return arrows;
}

}  // namespace hexadapt::render
