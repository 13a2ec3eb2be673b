// Half-space clipping of convex pieces: the exact kernel of the imprint (imprint.h).
//
// A region is kept where n.p - d <= 0. Polygons lie in the xy plane; polyhedra are lists of
// planar faces whose vertices go counter-clockwise seen from outside. Clipping a polygon
// that is not convex by a convex region still gives the exact area (Sutherland-Hodgman
// only leaves zero-area slivers); polyhedra must be convex.
#pragma once

#include <vector>

#include "hexadapt/mesh/geometry.h"

namespace hexadapt::clip {

struct Plane {
  Vec3 n;        ///< outward normal (unit length)
  double d = 0;  ///< offset: the plane is n.p = d
  double side(const Vec3& p) const { return n.dot(p) - d; }
};

using Polygon = std::vector<Vec3>;

struct Polyhedron {
  std::vector<Polygon> faces;
};

/// Signed area of a polygon in the xy plane (positive counter-clockwise).
double polygon_area(const Polygon& p);
/// The part of `p` where plane.side <= 0 (into `out`, which is overwritten).
void clip_polygon(const Polygon& p, const Plane& plane, Polygon& out);

/// The tetrahedron a, b, c, d, which must be positively oriented.
Polyhedron tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Signed volume of the tetrahedron (positive when d is on the left of a, b, c).
double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Volume of a closed polyhedron with outward faces.
double polyhedron_volume(const Polyhedron& p);
/// Cuts `p` by the plane, keeping the side <= 0 and closing the cut with a cap face.
void clip_polyhedron(Polyhedron& p, const Plane& plane);

/// The plane through a, b, c with normal (b - a) x (c - a); a zero normal for collinear points.
Plane plane_through(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace hexadapt::clip
