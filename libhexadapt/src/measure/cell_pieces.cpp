// Tetrahedra of hexes and convex pieces of input cells (rules: cell_pieces.h).
#include "cell_pieces.h"

#include <algorithm>
#include <cmath>

namespace hexadapt::clip {

namespace {

// The largest notch, relative to the cell, still taken out of the hull (hull_and_notches).
constexpr double max_notch_share = 0.05;

Vec3 node(const io::MeshData& d, index_t cell, int k) {
  return d.points[d.cells[static_cast<std::size_t>(cell) *
                              static_cast<std::size_t>(d.nodes_per_cell()) +
                          static_cast<std::size_t>(k)]
                      .idx()];
}
NodeId node_id(const io::MeshData& d, index_t cell, int k) {
  return d.cells[static_cast<std::size_t>(cell) * static_cast<std::size_t>(d.nodes_per_cell()) +
                 static_cast<std::size_t>(k)];
}

// The two triangles of local face f, split through its node of lowest global id; corners
// counter-clockwise from outside.
std::array<std::array<int, 3>, 2> face_triangles(const io::MeshData& d, index_t cell, int f) {
  const auto& q = ref_hex::face_nodes[static_cast<std::size_t>(f)];
  int lo = 0;
  for (int k = 1; k < 4; ++k)
    if (node_id(d, cell, q[static_cast<std::size_t>(k)]).value() <
        node_id(d, cell, q[static_cast<std::size_t>(lo)]).value())
      lo = k;
  const int s = lo % 2;  // 0: diagonal q0-q2, 1: diagonal q1-q3
  auto at = [&](int k) { return q[static_cast<std::size_t>((k + s) % 4)]; };
  return {{{at(0), at(1), at(2)}, {at(0), at(2), at(3)}}};
}

Vec3 hex_centroid(const io::MeshData& d, index_t cell) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < 8; ++k) c += node(d, cell, k);
  return c / 8.0;
}

Eigen::AlignedBox3d cell_box(const io::MeshData& d, index_t cell) {
  Eigen::AlignedBox3d box;
  for (int k = 0; k < d.nodes_per_cell(); ++k) box.extend(node(d, cell, k));
  return box;
}

double diagonal(const io::MeshData& d, index_t cell) {
  return cell_box(d, cell).diagonal().norm();
}

// True when every corner is inside (or within tol of) every plane.
bool contains_corners(const io::MeshData& d, index_t cell, const std::vector<Plane>& planes,
                      double tol) {
  for (const Plane& pl : planes)
    for (int k = 0; k < d.nodes_per_cell(); ++k)
      if (pl.side(node(d, cell, k)) > tol) return false;
  return true;
}

std::vector<Plane> tet_planes(const Tet& t) {
  const auto& p = t.p;
  return {plane_through(p[0], p[2], p[1]), plane_through(p[0], p[1], p[3]),
          plane_through(p[0], p[3], p[2]), plane_through(p[1], p[2], p[3])};
}

Piece tet_piece(const Tet& t, double sign) {
  Piece piece{tet_planes(t), {}, sign};
  for (const Vec3& p : t.p) piece.box.extend(p);
  return piece;
}

// The hull H of the hex with every folded face bent outwards, as planes, and the notches
// that H has in excess: where a face's chosen diagonal makes a valley, the face's other
// diagonal makes a ridge, and the two differ by the tetrahedron of the face's corners.
void hull_and_notches(const io::MeshData& d, index_t cell, double eps, std::vector<Plane>& planes,
                      std::vector<Tet>& notches) {
  for (int f = 0; f < 6; ++f) {
    const auto tri = face_triangles(d, cell, f);
    const Vec3 q0 = node(d, cell, tri[0][0]), q1 = node(d, cell, tri[0][1]),
               q2 = node(d, cell, tri[0][2]), q3 = node(d, cell, tri[1][2]);
    const Plane a = plane_through(q0, q1, q2);
    const double fold = a.side(q3);
    if (std::abs(fold) <= eps) {
      planes.push_back(a);  // planar
    } else if (fold < 0) {
      planes.push_back(a);  // a ridge: both triangles bound H
      planes.push_back(plane_through(q0, q2, q3));
    } else {
      planes.push_back(plane_through(q1, q2, q3));  // a valley: H takes the other diagonal
      planes.push_back(plane_through(q1, q3, q0));
      Tet notch{{q0, q1, q2, q3}, 1.0};
      if (tet_volume(q0, q1, q2, q3) < 0) std::swap(notch.p[2], notch.p[3]);
      notches.push_back(notch);
    }
  }
}

std::vector<Piece> hex_pieces(const io::MeshData& d, index_t cell, double tol, double* volume) {
  const std::array<Tet, 12> tets = hex_tets(d, cell);
  *volume = 0;
  for (const Tet& t : tets) *volume += t.sign * tet_volume(t.p[0], t.p[1], t.p[2], t.p[3]);
  const double eps = tol * diagonal(d, cell);
  std::vector<Plane> planes;
  std::vector<Tet> notches;
  hull_and_notches(d, cell, eps, planes, notches);
  const bool degenerate =
      std::any_of(planes.begin(), planes.end(), [](const Plane& p) { return p.n.isZero(); });
  // Thin notches stay near their face, apart from each other: then the cell is exactly H
  // minus the notches (pieces of sign -1). Otherwise the cell is its 12 tets.
  double notch_volume = 0;
  for (const Tet& t : notches)
    notch_volume = std::max(notch_volume, tet_volume(t.p[0], t.p[1], t.p[2], t.p[3]));
  if (!degenerate && *volume > 0 && notch_volume <= max_notch_share * *volume &&
      contains_corners(d, cell, planes, eps)) {
    std::vector<Piece> pieces{{planes, cell_box(d, cell), 1.0}};
    for (const Tet& t : notches) pieces.push_back(tet_piece(t, -1.0));
    return pieces;
  }
  std::vector<Piece> pieces;
  for (const Tet& t : tets)
    if (t.sign > 0) pieces.push_back(tet_piece(t, 1.0));
  return pieces;
}

Plane edge_plane(const Vec3& a, const Vec3& b) {
  // Outward normal of a counter-clockwise edge a -> b in the xy plane.
  Vec3 n(b.y() - a.y(), a.x() - b.x(), 0.0);
  const double len = n.norm();
  if (len > 0) n /= len;
  return {n, n.dot(0.5 * (a + b))};
}

std::vector<Plane> polygon_planes(const std::vector<Vec3>& p) {
  std::vector<Plane> planes;
  for (std::size_t i = 0; i < p.size(); ++i)
    planes.push_back(edge_plane(p[i], p[(i + 1) % p.size()]));
  return planes;
}

double cross_z(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

std::vector<Piece> quad_pieces(const io::MeshData& d, index_t cell, double tol, double* volume) {
  double sign = 1;
  const Polygon q = quad_polygon(d, cell, &sign);
  *volume = sign * polygon_area(q);
  if (sign < 0) return {};  // an inverted input cell holds no material
  const double eps = tol * diagonal(d, cell) * diagonal(d, cell);
  int reflex = -1;
  for (int i = 0; i < 4; ++i)
    if (cross_z(q[static_cast<std::size_t>((i + 3) % 4)], q[static_cast<std::size_t>(i)],
                q[static_cast<std::size_t>((i + 1) % 4)]) < -eps)
      reflex = i;
  if (reflex < 0) return {{polygon_planes(q), cell_box(d, cell), 1.0}};
  // A dart: split along the diagonal through the reflex corner.
  auto at = [&](int k) { return q[static_cast<std::size_t>((reflex + k) % 4)]; };
  auto piece = [](const Polygon& t) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : t) box.extend(p);
    return Piece{polygon_planes(t), box, 1.0};
  };
  return {piece({at(0), at(1), at(2)}), piece({at(0), at(2), at(3)})};
}

}  // namespace

std::array<Tet, 12> hex_tets(const io::MeshData& d, index_t cell) {
  const Vec3 x = hex_centroid(d, cell);
  std::array<Tet, 12> tets;
  int k = 0;
  for (int f = 0; f < 6; ++f)
    for (const auto& tri : face_triangles(d, cell, f)) {
      Tet t{{x, node(d, cell, tri[0]), node(d, cell, tri[1]), node(d, cell, tri[2])}, 1.0};
      if (tet_volume(t.p[0], t.p[1], t.p[2], t.p[3]) < 0) {
        std::swap(t.p[2], t.p[3]);
        t.sign = -1;
      }
      tets[static_cast<std::size_t>(k++)] = t;
    }
  return tets;
}

Polygon quad_polygon(const io::MeshData& d, index_t cell, double* sign) {
  Polygon q = {node(d, cell, 0), node(d, cell, 1), node(d, cell, 2), node(d, cell, 3)};
  *sign = 1;
  if (polygon_area(q) < 0) {
    std::reverse(q.begin(), q.end());
    *sign = -1;
  }
  return q;
}

std::vector<Piece> convex_pieces(const io::MeshData& data, index_t cell, double tolerance,
                                 double* volume) {
  return data.dim == 3 ? hex_pieces(data, cell, tolerance, volume)
                       : quad_pieces(data, cell, tolerance, volume);
}

}  // namespace hexadapt::clip
