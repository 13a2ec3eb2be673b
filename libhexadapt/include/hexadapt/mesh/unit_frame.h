// UnitFrame: the frame a stage computes in, so that a grid meshes alike in any unit and place.
//
// world = local * 2^exponent + origin. The exponent brings the grid's largest extent (along
// x, y or z) into [1, 2): scaling by a power of two is exact, so a grid in metres and the same grid
// in any power-of-two multiple of metres go through the same arithmetic, and squared lengths and
// volumes neither underflow (a grid at 1e-300) nor overflow (at 1e300). The origin is the
// lowest corner when the grid lies farther from the point of coordinates 0 than its own size
// (cells of 0.1 at 1e6 would lose digits in every difference), else 0.
#pragma once

#include <cmath>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt {

struct UnitFrame {
  Vec3 origin = Vec3::Zero();
  int exponent = 0;

  bool is_identity() const { return exponent == 0 && origin == Vec3::Zero(); }
  Vec3 to_local(const Vec3& world) const { return scaled(world - origin, -exponent); }
  Vec3 to_world(const Vec3& local) const { return scaled(local, exponent) + origin; }
  /// A length (power 1), area (2) or volume (3) in local units.
  double to_local(double world, int power = 1) const {
    return std::ldexp(world, -exponent * power);
  }
  /// A length (power 1), area (2) or volume (3) back in world units.
  double to_world(double local, int power = 1) const { return std::ldexp(local, exponent * power); }

 private:
  static Vec3 scaled(const Vec3& v, int e) {
    return Vec3(std::ldexp(v.x(), e), std::ldexp(v.y(), e), std::ldexp(v.z(), e));
  }
};

/// The power of two e with size x 2^-e in [1, 2); 0 for a size that is not positive and finite.
int unit_exponent(double size);

/// The frame of these points (identity when there are none or one is not finite).
UnitFrame unit_frame(const std::vector<Vec3>& points);
template <class M>
UnitFrame unit_frame(const M& mesh);

/// unit_frame when the points' size lies beyond 2^+-64, where squared lengths and volumes
/// come near the ends of the double range; else the identity. For computations whose
/// tolerances are relative, which then need no copy of a usual grid.
UnitFrame far_unit_frame(const std::vector<Vec3>& points);
template <class M>
UnitFrame far_unit_frame(const M& mesh);

/// The frames of a mesh spread over ranks, each holding a part: the frames of the whole mesh,
/// the same bits on every rank (from every rank's bounding box).
template <class M>
UnitFrame unit_frame(const M& mesh, const dist::Communicator& comm);
template <class M>
UnitFrame far_unit_frame(const M& mesh, const dist::Communicator& comm);

/// The mesh with every point moved into (from) the frame; the same topology.
template <class M>
M to_local(const M& mesh, const UnitFrame& frame);
template <class M>
M to_world(const M& mesh, const UnitFrame& frame);

}  // namespace hexadapt
