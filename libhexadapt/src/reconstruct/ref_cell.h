// Reference-cell tables of the pixel lattice, for 2D (quad) and 3D (hex) at run time.
//
// A coarse cell is split into nsub^d pixels by the bilinear / trilinear map of its corners;
// pixel (i, j[, k]) covers [i, i+1] x [j, j+1] (x [k, k+1]) of the lattice [0, nsub]^d.
// Corners, faces and their outward order follow geometry.h (quads counter-clockwise, hexes in
// binary order) so that a pixel is a small copy of its coarse cell.
#pragma once

#include <array>

namespace hexadapt::reconstruct::detail {

struct RefCell {
  int dim;
  int n_corners;
  int n_faces;
  int nodes_per_face;
  std::array<std::array<int, 3>, 8> corner;     ///< lattice offset (0/1 per axis) of corner v
  std::array<std::array<int, 4>, 6> face;       ///< corners of local face lf, outward order
  std::array<int, 6> face_axis;                 ///< the axis normal to local face lf
  std::array<int, 6> face_side;                 ///< 0: the face at coordinate 0, 1: at 1
};

inline constexpr RefCell ref_quad_cell = {
    2, 4, 4, 2,
    {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}}},
    {{{0, 1, 0, 0}, {1, 2, 0, 0}, {2, 3, 0, 0}, {3, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}}},
    {1, 0, 1, 0, 0, 0},
    {0, 1, 1, 0, 0, 0}};

inline constexpr RefCell ref_hex_cell = {
    3, 8, 6, 4,
    {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}},
    {{{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}},
    {0, 0, 1, 1, 2, 2},
    {0, 1, 0, 1, 0, 1}};

inline const RefCell& ref_cell(int dim) { return dim == 3 ? ref_hex_cell : ref_quad_cell; }

}  // namespace hexadapt::reconstruct::detail
