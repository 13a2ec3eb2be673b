// Shapes: the initial (time 0) material regions of a generated case, and an analytic
// classification of any point (DESIGN sec. 7: synthetic stand-ins for the paper's inputs).
//
// A Layout paints primitives (balls, boxes, regions below a wavy graph, a noisy ball) over a
// background material; the last primitive containing a point decides its material. Every
// primitive also gives a lower bound on the distance from a point to its own boundary, so
// the layout can bound the distance to the nearest interface (the boundaries of the painted
// regions lie on the primitives' boundaries): a cell inside that distance is pure without
// sampling. Points are 3D; 2D cases live in z = 0 and use primitives unbounded in z.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "hexadapt/core/geometry.h"

namespace hexadapt::generate {

/// A region of space with a conservative distance to its boundary.
class Primitive {
 public:
  virtual ~Primitive() = default;
  virtual bool contains(const Vec3& p) const = 0;
  /// A lower bound on the distance from p to the region's boundary (0 when unknown).
  virtual double boundary_distance(const Vec3& p) const = 0;
};

/// The open ball |p - centre| < radius (a disk when centre.z() == 0 and points are 2D).
class Ball final : public Primitive {
 public:
  Ball(const Vec3& centre, double radius) : centre_(centre), radius_(radius) {}
  bool contains(const Vec3& p) const override;
  double boundary_distance(const Vec3& p) const override;

 private:
  Vec3 centre_;
  double radius_;
};

/// The half-open box lo <= p < hi; bounds may be infinite.
class Box final : public Primitive {
 public:
  Box(const Vec3& lo, const Vec3& hi) : lo_(lo), hi_(hi) {}
  bool contains(const Vec3& p) const override;
  double boundary_distance(const Vec3& p) const override;

 private:
  Vec3 lo_, hi_;
};

/// The points below a wavy graph: p[vertical] < level + amplitude * prod_i sin(2 pi k p[i] +
/// phase_i) over the horizontal axes (x in 2D; x and y in 3D).
class BelowGraph final : public Primitive {
 public:
  BelowGraph(int dim, double level, double amplitude, double wavenumber, double phase);
  bool contains(const Vec3& p) const override;
  double boundary_distance(const Vec3& p) const override;
  double height(const Vec3& p) const;

 private:
  int dim_;
  double level_, amplitude_, wavenumber_, phase_;
};

/// A ball whose radius varies with the direction: R (1 + A n(d)), n a seeded sum of a few
/// low-frequency waves in the unit direction d with |n| <= 1 (the "asteroid").
class NoisyBall final : public Primitive {
 public:
  NoisyBall(const Vec3& centre, double radius, double amplitude, std::uint64_t seed);
  bool contains(const Vec3& p) const override;
  double boundary_distance(const Vec3& p) const override;
  /// The surface radius in the direction of p (relative to the centre).
  double surface_radius(const Vec3& p) const;

 private:
  struct Wave {
    Vec3 direction;
    double frequency, phase, weight;
  };
  Vec3 centre_;
  double radius_, amplitude_;
  std::vector<Wave> waves_;
};

/// A background material with primitives painted over it, in order.
class Layout {
 public:
  explicit Layout(int background = 0) : background_(background) {}
  /// Points in `region` take `material` (later paints win).
  Layout& paint(int material, std::shared_ptr<const Primitive> region);

  int material_at(const Vec3& p) const;
  /// A lower bound on the distance from p to the nearest interface between materials.
  double clearance(const Vec3& p) const;
  int n_regions() const { return static_cast<int>(regions_.size()); }
  /// The largest material index the layout can return.
  int max_material() const;

 private:
  int background_;
  std::vector<std::pair<int, std::shared_ptr<const Primitive>>> regions_;
};

}  // namespace hexadapt::generate
