#include "hexadapt/generate/flows.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hexadapt/core/error.h"

namespace hexadapt::generate {

namespace {

double square(double x) {
  return x * x;
}

double horizontal_distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}
}  // namespace

Vec3 SingleVortex::velocity(const Vec3& p, double t) const {
  const double g = std::cos(pi * t / period_);
  const double sx = std::sin(pi * p.x()), sy = std::sin(pi * p.y());
  return {-sx * sx * std::sin(2 * pi * p.y()) * g, std::sin(2 * pi * p.x()) * sy * sy * g, 0.0};
}

double SingleVortex::rate() const {
  return 2 * pi;
}

Vec3 Deformation3D::velocity(const Vec3& p, double t) const {
  const double g = std::cos(pi * t / period_);
  const double s2x = std::sin(2 * pi * p.x()), s2y = std::sin(2 * pi * p.y()),
               s2z = std::sin(2 * pi * p.z());
  return {2 * square(std::sin(pi * p.x())) * s2y * s2z * g,
          -s2x * square(std::sin(pi * p.y())) * s2z * g,
          -s2x * s2y * square(std::sin(pi * p.z())) * g};
}

double Deformation3D::rate() const {
  return 4 * pi;
}

Vec3 CompactVortex::velocity(const Vec3& p, double) const {
  const double dx = p.x() - centre_.x(), dy = p.y() - centre_.y();
  const double s = (dx * dx + dy * dy) / (radius_ * radius_);
  if (s >= 1) return Vec3::Zero();
  const double w = omega_ * (1 - s) * (1 - s) * (1 - s);
  return {-w * dy, w * dx, 0.0};
}

// |grad u| <= |omega| + max r |omega'(r)| = |omega| (1 + 6 max s (1 - s)^2) < 2 |omega|.
double CompactVortex::rate() const {
  return 2 * std::abs(omega_);
}

bool CompactVortex::still_in(const Vec3& c, double r) const {
  return horizontal_distance(c, centre_) >= radius_ + r;
}

DropFlow::DropFlow(int dim, const Vec3& centre, double radius, double speed)
    : dim_(dim), centre_(centre), radius_(radius), a_(-speed / (dim - 1)) {
  if (dim != 2 && dim != 3) throw InternalError("DropFlow: dimension must be 2 or 3");
}

Vec3 DropFlow::velocity(const Vec3& p, double) const {
  const int vertical = dim_ - 1;
  Vec3 d = p - centre_;
  if (dim_ == 2) d.z() = 0;
  const double r2 = radius_ * radius_;
  const double s = d.squaredNorm();
  if (s >= r2) return Vec3::Zero();
  const double q = 1 - s / r2;
  const double g = q * q * q, dg = -3 * q * q / r2;
  const double v = d[vertical];
  const double h2 = s - v * v;
  Vec3 u = Vec3::Zero();
  for (int a = 0; a < vertical; ++a) u[a] = -2 * a_ * d[a] * v * dg;
  u[vertical] = a_ * ((dim_ - 1) * g + 2 * h2 * dg);
  return u;
}

// The velocity gradient scales as speed / R; the factor covers the profile's derivatives.
double DropFlow::rate() const {
  return 12 * std::abs(a_) * (dim_ - 1) / radius_;
}

bool DropFlow::still_in(const Vec3& c, double r) const {
  Vec3 d = c - centre_;
  if (dim_ == 2) d.z() = 0;
  return d.norm() >= radius_ + r;
}

Vec3 SumFlow::velocity(const Vec3& p, double t) const {
  Vec3 u = Vec3::Zero();
  for (const auto& f : parts_) u += f->velocity(p, t);
  return u;
}

double SumFlow::rate() const {
  double r = 0;
  for (const auto& f : parts_) r += f->rate();
  return r;
}

bool SumFlow::still_in(const Vec3& c, double r) const {
  return std::all_of(parts_.begin(), parts_.end(),
                     [&](const auto& f) { return f->still_in(c, r); });
}

Vec3 trace_back(const Flow& flow, const Vec3& p, double t, int steps) {
  if (t == 0 || steps < 1) return p;
  const double h = -t / steps;
  Vec3 x = p;
  for (int i = 0; i < steps; ++i) {
    const double tau = t + i * h;
    const Vec3 k1 = flow.velocity(x, tau);
    const Vec3 k2 = flow.velocity(x + 0.5 * h * k1, tau + 0.5 * h);
    const Vec3 k3 = flow.velocity(x + 0.5 * h * k2, tau + 0.5 * h);
    const Vec3 k4 = flow.velocity(x + h * k3, tau + h);
    x += (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return x;
}

int automatic_steps(const Flow& flow, double t) {
  if (!std::isfinite(t)) throw OptionError("flow time must be a finite number");
  // In double first: the cast to int of a value beyond its range is undefined.
  const double steps = std::ceil(4 * flow.rate() * std::abs(t));
  if (!(steps <= max_rk4_steps)) {
    std::ostringstream m;
    m << "flow time " << t << " needs " << steps << " RK4 steps, more than " << max_rk4_steps;
    throw OptionError(m.str());
  }
  return std::max(1, static_cast<int>(steps));
}

}  // namespace hexadapt::generate
