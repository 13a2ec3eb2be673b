#include "hexadapt/mesh/plane_cut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hexadapt {

namespace {

double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return std::abs((b - a).dot((c - a).cross(d - a))) / 6.0;
}

Vec3 edge_cut(const Vec3& p, double hp, const Vec3& q, double hq) {
  return p + (hp / (hp - hq)) * (q - p);
}

// Volume of the part of tet v where h >= 0 (h the signed plane distances of the corners).
double tet_above(const std::array<Vec3, 4>& v, const std::array<double, 4>& h) {
  std::array<int, 4> pos{}, neg{};
  int np = 0, nn = 0;
  for (int i = 0; i < 4; ++i) {
    if (h[static_cast<std::size_t>(i)] >= 0)
      pos[static_cast<std::size_t>(np++)] = i;
    else
      neg[static_cast<std::size_t>(nn++)] = i;
  }
  const auto V = [&](int i) { return v[static_cast<std::size_t>(i)]; };
  const auto H = [&](int i) { return h[static_cast<std::size_t>(i)]; };
  const auto cut = [&](int i, int j) { return edge_cut(V(i), H(i), V(j), H(j)); };
  const double whole = tet_volume(v[0], v[1], v[2], v[3]);
  if (np == 0) return 0;
  if (np == 4) return whole;
  if (np == 1) {
    const int a = pos[0];
    return tet_volume(V(a), cut(a, neg[0]), cut(a, neg[1]), cut(a, neg[2]));
  }
  if (np == 3) {
    const int a = neg[0];
    return whole - tet_volume(V(a), cut(a, pos[0]), cut(a, pos[1]), cut(a, pos[2]));
  }
  // Two corners on each side: the positive part is a prism a, ac, ad | b, bc, bd.
  const int a = pos[0], b = pos[1], c = neg[0], d = neg[1];
  const Vec3 ac = cut(a, c), ad = cut(a, d), bc = cut(b, c), bd = cut(b, d);
  return tet_volume(V(a), ac, ad, bd) + tet_volume(V(a), ac, bc, bd) +
         tet_volume(V(a), V(b), bc, bd);
}

// The six tets around the diagonal 0-7 of a binary-ordered hex.
constexpr std::array<std::array<int, 2>, 6> kHexPaths = {
    {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}}};

double polygon_area(const std::vector<Vec3>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& u = p[i];
    const Vec3& w = p[(i + 1) % p.size()];
    a += u.x() * w.y() - w.x() * u.y();
  }
  return std::abs(a) / 2;
}

}  // namespace

template <class M>
double volume_above_plane(const M& mesh, CellId c, const Vec3& n, double s) {
  const auto nodes = mesh.cell_nodes(c);
  if constexpr (M::dim == 2) {
    std::vector<Vec3> kept;
    for (int i = 0; i < 4; ++i) {
      const Vec3 p = mesh.point(nodes[static_cast<std::size_t>(i)]);
      const Vec3 q = mesh.point(nodes[static_cast<std::size_t>((i + 1) % 4)]);
      const double hp = n.dot(p) - s, hq = n.dot(q) - s;
      if (hp >= 0) kept.push_back(p);
      if ((hp >= 0) != (hq >= 0)) kept.push_back(edge_cut(p, hp, q, hq));
    }
    return kept.size() < 3 ? 0.0 : polygon_area(kept);
  } else {
    const auto P = [&](int i) { return mesh.point(nodes[static_cast<std::size_t>(i)]); };
    double sum = 0;
    for (const auto& path : kHexPaths) {
      const std::array<Vec3, 4> v = {P(0), P(path[0]), P(path[1]), P(7)};
      std::array<double, 4> h{};
      for (std::size_t i = 0; i < 4; ++i) h[i] = n.dot(v[i]) - s;
      sum += tet_above(v, h);
    }
    return sum;
  }
}

template <class M>
std::optional<double> plane_offset_for_share(const M& mesh, CellId c, const Vec3& n, double share) {
  if (!(share > 0 && share < 1)) return std::nullopt;
  double lo = n.dot(mesh.point(mesh.cell_nodes(c)[0])), hi = lo;
  for (NodeId v : mesh.cell_nodes(c)) {
    lo = std::min(lo, n.dot(mesh.point(v)));
    hi = std::max(hi, n.dot(mesh.point(v)));
  }
  const double whole = volume_above_plane(mesh, c, n, lo);
  if (!(whole > 0) || !(hi > lo)) return std::nullopt;
  const double goal = share * whole;
  // volume_above_plane decreases from `whole` at lo to 0 at hi. Down to the rounding of the
  // offsets, relative to the cell's extent and its distance from the origin: the same in
  // any unit.
  const double span = hi - lo;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * (span + std::abs(lo) + std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi);
    if (volume_above_plane(mesh, c, n, mid) > goal)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

#define HEXADAPT_INSTANTIATE(M)                                                 \
  template double volume_above_plane<M>(const M&, CellId, const Vec3&, double); \
  template std::optional<double> plane_offset_for_share<M>(const M&, CellId, const Vec3&, double);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
