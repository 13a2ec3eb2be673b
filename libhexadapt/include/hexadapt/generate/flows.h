// Flows: divergence-free velocity fields that deform the initial regions of a generated case,
// and the RK4 back-tracing that finds where a point at time t came from (DESIGN sec. 7).
//
// A real advection code moves material along such fields; tracing a sample point back to
// time 0 and classifying it by the initial shapes gives the fraction field that code would
// produce (filaments, roll-ups, triple junctions) without its numerical diffusion. Every
// field here has zero divergence, so areas and volumes are preserved: the tests check it.
#pragma once

#include <memory>
#include <vector>

#include "hexadapt/core/geometry.h"

namespace hexadapt::generate {

inline constexpr double pi = 3.141592653589793;

class Flow {
 public:
  virtual ~Flow() = default;
  virtual Vec3 velocity(const Vec3& p, double t) const = 0;
  /// An upper estimate of |grad u| (1 / time): the automatic RK4 step is a fraction of 1/rate.
  virtual double rate() const = 0;
  /// True when the velocity is zero in the whole ball (c, r) at every time: its points never
  /// move, and RK4 leaves them exactly in place.
  virtual bool still_in(const Vec3& /*c*/, double /*r*/) const { return false; }
};

/// Rider-Kothe single vortex on [0,1]^2, reversed with period T:
/// u = -sin^2(pi x) sin(2 pi y) cos(pi t / T), v = sin(2 pi x) sin^2(pi y) cos(pi t / T).
class SingleVortex final : public Flow {
 public:
  explicit SingleVortex(double period) : period_(period) {}
  Vec3 velocity(const Vec3& p, double t) const override;
  double rate() const override;

 private:
  double period_;
};

/// LeVeque's 3D deformation flow on [0,1]^3, reversed with period T:
/// u = 2 sin^2(pi x) sin(2 pi y) sin(2 pi z) g, v = -sin(2 pi x) sin^2(pi y) sin(2 pi z) g,
/// w = -sin(2 pi x) sin(2 pi y) sin^2(pi z) g, g = cos(pi t / T).
class Deformation3D final : public Flow {
 public:
  explicit Deformation3D(double period) : period_(period) {}
  Vec3 velocity(const Vec3& p, double t) const override;
  double rate() const override;

 private:
  double period_;
};

/// A steady vortex about the axis through `centre` along z with compact support: angular
/// velocity omega (1 - r^2 / R^2)^3 for r < R, zero beyond (negative omega: clockwise).
/// Purely azimuthal, hence divergence-free; the differential rotation rolls interfaces up.
class CompactVortex final : public Flow {
 public:
  CompactVortex(const Vec3& centre, double radius, double omega)
      : centre_(centre), radius_(radius), omega_(omega) {}
  Vec3 velocity(const Vec3& p, double t) const override;
  double rate() const override;
  bool still_in(const Vec3& c, double r) const override;

 private:
  Vec3 centre_;
  double radius_, omega_;
};

/// An axisymmetric circulation inside the ball (centre, R) about the vertical axis (y in 2D,
/// z in 3D), the shape of a falling drop's wake: down the axis at `speed` (at the centre),
/// up along the sides. With s = |p - c|^2, g = (1 - s / R^2)^3, h the horizontal offset and
/// v the vertical one: u_h = -2 A h v g'(s), u_v = A ((d - 1) g + 2 |h|^2 g'(s)), A = -speed
/// / (d - 1): divergence-free in d = 2 and 3, zero outside the ball.
class DropFlow final : public Flow {
 public:
  DropFlow(int dim, const Vec3& centre, double radius, double speed);
  Vec3 velocity(const Vec3& p, double t) const override;
  double rate() const override;
  bool still_in(const Vec3& c, double r) const override;

 private:
  int dim_;
  Vec3 centre_;
  double radius_, a_;
};

/// The sum of several flows (e.g. vortices with disjoint supports).
class SumFlow final : public Flow {
 public:
  explicit SumFlow(std::vector<std::shared_ptr<const Flow>> parts) : parts_(std::move(parts)) {}
  Vec3 velocity(const Vec3& p, double t) const override;
  double rate() const override;
  bool still_in(const Vec3& c, double r) const override;

 private:
  std::vector<std::shared_ptr<const Flow>> parts_;
};

/// Where the point p at time t was at time 0: `steps` classical RK4 steps backwards in time.
Vec3 trace_back(const Flow& flow, const Vec3& p, double t, int steps);

/// The most RK4 steps automatic_steps gives (a longer flow time is refused, not truncated).
inline constexpr int max_rk4_steps = 1'000'000;

/// The automatic step count for tracing over [0, t]: ceil(4 * rate * |t|), at least 1.
/// Throws OptionError when t is not finite or needs more than max_rk4_steps.
int automatic_steps(const Flow& flow, double t);

}  // namespace hexadapt::generate
