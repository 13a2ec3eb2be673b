#include "hexadapt/generate/shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"
#include "random.h"

namespace hexadapt::generate {

namespace {
constexpr double two_pi = 6.283185307179586;
}

bool Ball::contains(const Vec3& p) const {
  return (p - centre_).squaredNorm() < radius_ * radius_;
}

double Ball::boundary_distance(const Vec3& p) const {
  return std::abs((p - centre_).norm() - radius_);
}

bool Box::contains(const Vec3& p) const {
  for (int a = 0; a < 3; ++a)
    if (!(p[a] >= lo_[a] && p[a] < hi_[a])) return false;
  return true;
}

double Box::boundary_distance(const Vec3& p) const {
  if (contains(p)) {
    double d = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) d = std::min({d, p[a] - lo_[a], hi_[a] - p[a]});
    return d;
  }
  // Outside: the largest per-axis gap is a lower bound on the Euclidean distance.
  double d = 0;
  for (int a = 0; a < 3; ++a) d = std::max({d, lo_[a] - p[a], p[a] - hi_[a]});
  return d;
}

BelowGraph::BelowGraph(int dim, double level, double amplitude, double wavenumber, double phase)
    : dim_(dim), level_(level), amplitude_(amplitude), wavenumber_(wavenumber), phase_(phase) {
  if (dim != 2 && dim != 3) throw InternalError("BelowGraph: dimension must be 2 or 3");
}

double BelowGraph::height(const Vec3& p) const {
  double h = amplitude_;
  for (int a = 0; a < dim_ - 1; ++a)
    h *= std::sin(two_pi * wavenumber_ * p[a] + phase_ + static_cast<double>(a));
  return level_ + h;
}

bool BelowGraph::contains(const Vec3& p) const {
  return p[dim_ - 1] < height(p);
}

double BelowGraph::boundary_distance(const Vec3& p) const {
  // The graph is Lipschitz with constant L: distance >= vertical gap / sqrt(1 + L^2).
  const double lip = std::abs(amplitude_) * two_pi * wavenumber_;
  return std::abs(p[dim_ - 1] - height(p)) / std::sqrt(1.0 + lip * lip);
}

NoisyBall::NoisyBall(const Vec3& centre, double radius, double amplitude, std::uint64_t seed)
    : centre_(centre), radius_(radius), amplitude_(amplitude) {
  constexpr int n_waves = 6;
  double total = 0;
  for (int k = 0; k < n_waves; ++k) {
    const auto u = [&](int i) {
      return detail::uniform(seed, 0x6e6f697365ULL, static_cast<std::uint64_t>(4 * k + i));
    };
    const double z = 2.0 * u(0) - 1.0, phi = two_pi * u(1), s = std::sqrt(1.0 - z * z);
    Wave w{Vec3(s * std::cos(phi), s * std::sin(phi), z), 1.5 + 2.5 * u(2), two_pi * u(3),
           1.0 / (1.0 + k)};
    total += w.weight;
    waves_.push_back(w);
  }
  for (auto& w : waves_) w.weight /= total;  // so that |n| <= 1
}

double NoisyBall::surface_radius(const Vec3& p) const {
  const Vec3 d = p - centre_;
  const double r = d.norm();
  if (r == 0) return radius_;
  double n = 0;
  for (const auto& w : waves_)
    n += w.weight * std::sin(w.frequency * w.direction.dot(d / r) + w.phase);
  return radius_ * (1.0 + amplitude_ * n);
}

bool NoisyBall::contains(const Vec3& p) const {
  return (p - centre_).norm() < surface_radius(p);
}

double NoisyBall::boundary_distance(const Vec3& p) const {
  // The surface lies in the shell R (1 +- A): outside it the shell gives the bound.
  const double r = (p - centre_).norm();
  const double outer = radius_ * (1.0 + std::abs(amplitude_));
  const double inner = radius_ * (1.0 - std::abs(amplitude_));
  return std::max({0.0, r - outer, inner - r});
}

Layout& Layout::paint(int material, std::shared_ptr<const Primitive> region) {
  regions_.emplace_back(material, std::move(region));
  return *this;
}

int Layout::material_at(const Vec3& p) const {
  for (auto it = regions_.rbegin(); it != regions_.rend(); ++it)
    if (it->second->contains(p)) return it->first;
  return background_;
}

int Layout::max_material() const {
  int m = background_;
  for (const auto& r : regions_) m = std::max(m, r.first);
  return m;
}

double Layout::clearance(const Vec3& p) const {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& r : regions_) d = std::min(d, r.second->boundary_distance(p));
  return d;
}

}  // namespace hexadapt::generate
