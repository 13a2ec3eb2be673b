#include "hexadapt/quality/scaled_jacobian.h"

#include <algorithm>
#include <cmath>

namespace hexadapt {

namespace {

constexpr double kTiny = 1e-300;

// det(a, b, c) / (|a| |b| |c|), or nullopt-like -2 marker for a degenerate frame.
bool scaled_det(const Vec3& a, const Vec3& b, const Vec3& c, double& out) {
  const double la = a.squaredNorm(), lb = b.squaredNorm(), lc = c.squaredNorm();
  if (la < kTiny || lb < kTiny || lc < kTiny) return false;
  out = a.dot(b.cross(c)) / std::sqrt(la * lb * lc);
  return true;
}

}  // namespace

double hex_scaled_jacobian(const std::array<Vec3, 8>& p) {
  // Principal axes: difference of the centroids of opposite faces (times 4).
  const Vec3 ax = (p[1] + p[3] + p[5] + p[7]) - (p[0] + p[2] + p[4] + p[6]);
  const Vec3 ay = (p[2] + p[3] + p[6] + p[7]) - (p[0] + p[1] + p[4] + p[5]);
  const Vec3 az = (p[4] + p[5] + p[6] + p[7]) - (p[0] + p[1] + p[2] + p[3]);
  double worst;
  if (!scaled_det(ax, ay, az, worst)) return -1.0;
  for (int v = 0; v < 8; ++v) {
    // Edges towards the neighbours along x, y, z; an odd number of "upper" bits flips the
    // frame's handedness, hence the sign.
    const auto u = static_cast<std::size_t>(v);
    const Vec3 a = p[u ^ 1u] - p[u], b = p[u ^ 2u] - p[u], c = p[u ^ 4u] - p[u];
    double j;
    if (!scaled_det(a, b, c, j)) return -1.0;
    const int parity = (v & 1) + ((v >> 1) & 1) + ((v >> 2) & 1);
    worst = std::min(worst, parity % 2 ? -j : j);
  }
  return std::clamp(worst, -1.0, 1.0);
}

double hex_volume(const std::array<Vec3, 8>& p) {
  const double g = 0.5 / std::sqrt(3.0);
  double vol = 0;
  for (int q = 0; q < 8; ++q) {
    const double s[3] = {0.5 + ((q & 1) ? g : -g), 0.5 + ((q & 2) ? g : -g),
                         0.5 + ((q & 4) ? g : -g)};
    Vec3 d[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (std::size_t v = 0; v < 8; ++v) {
      for (int axis = 0; axis < 3; ++axis) {
        // d/ds_axis of the trilinear shape function of node v.
        double w = ((v >> axis) & 1u) ? 1.0 : -1.0;
        for (int o = 0; o < 3; ++o) {
          if (o == axis) continue;
          w *= ((v >> o) & 1u) ? s[o] : 1.0 - s[o];
        }
        d[axis] += w * p[v];
      }
    }
    vol += d[0].dot(d[1].cross(d[2])) / 8.0;
  }
  return vol;
}

double quad_scaled_jacobian(const std::array<Vec3, 4>& p) {
  double worst = 1.0;
  for (std::size_t v = 0; v < 4; ++v) {
    const Vec3 a = p[(v + 1) % 4] - p[v], b = p[(v + 3) % 4] - p[v];
    const double la = a.head<2>().squaredNorm(), lb = b.head<2>().squaredNorm();
    if (la < kTiny || lb < kTiny) return -1.0;
    worst = std::min(worst, (a.x() * b.y() - a.y() * b.x()) / std::sqrt(la * lb));
  }
  return std::clamp(worst, -1.0, 1.0);
}

double quad_area(const std::array<Vec3, 4>& p) {
  return 0.5 * ((p[2].x() - p[0].x()) * (p[3].y() - p[1].y()) -
                (p[3].x() - p[1].x()) * (p[2].y() - p[0].y()));
}

}  // namespace hexadapt
