// Half-space clipping of convex pieces: the exact kernel of the imprint (imprint.h).
//
// A region is kept where n.p - d <= 0. Polygons lie in the xy plane; polyhedra are lists of
// planar faces whose vertices go counter-clockwise seen from outside. Clipping a polygon
// that is not convex by a convex region still gives the exact area (Sutherland-Hodgman
// only leaves zero-area slivers); polyhedra must be convex.
#pragma once

#include <vector>

#include "hexadapt/core/geometry.h"

namespace hexadapt::clip {

struct Plane {
  Vec3 n;        ///< outward normal (unit length)
  double d = 0;  ///< offset: the plane is n.p = d
  double side(const Vec3& p) const { return n.dot(p) - d; }
};

using Polygon = std::vector<Vec3>;

/// Faces stored one after the other (no allocation once the buffers have grown): face f
/// is points[begin(f) .. end[f]).
struct Polyhedron {
  std::vector<Vec3> points;
  std::vector<std::size_t> end;
  std::size_t n_faces() const { return end.size(); }
  std::size_t begin(std::size_t f) const { return f == 0 ? 0 : end[f - 1]; }
  void clear() {
    points.clear();
    end.clear();
  }
  void close_face() { end.push_back(points.size()); }
};

/// Signed area of a polygon in the xy plane (positive counter-clockwise).
double polygon_area(const Polygon& p);
/// The part of `p` where plane.side <= 0 (into `out`, which is overwritten).
void clip_polygon(const Polygon& p, const Plane& plane, Polygon& out);

/// The tetrahedron a, b, c, d (positively oriented) into `out`.
void tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Polyhedron& out);
/// Signed volume of the tetrahedron (positive when d is on the left of a, b, c).
double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Volume of a closed polyhedron with outward faces.
double polyhedron_volume(const Polyhedron& p);
/// Cuts `p` by the plane, keeping the side <= 0 and closing the cut with a cap face;
/// `scratch` is working memory.
void clip_polyhedron(Polyhedron& p, const Plane& plane, Polyhedron& scratch);

/// Volume of the part of tetrahedron a, b, c, d where every plane's side is <= 0, clipped
/// as a list of tetrahedra into `volume`. Returns false (volume untouched) when the list
/// would grow too long; the caller then clips the tetrahedron as a polyhedron.
bool clipped_tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                        const Plane* const* planes, std::size_t n_planes, double* volume);

/// The plane through a, b, c with normal (b - a) x (c - a); a zero normal for collinear points.
Plane plane_through(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace hexadapt::clip
