// Points and the reference cells: the tables every algorithm navigates cells with.
//
// Quads are stored counter-clockwise (VTK order); hexes in binary lattice order
// v = i + 2j + 4k, the same as VTK_VOXEL (the IO layer converts VTK_HEXAHEDRON with
// vtk_to_binary below). The faces of the reference hex are listed with outward normals.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace hexadapt {

using Vec3 = Eigen::Vector3d;

/// Reference quad, counter-clockwise; local edge e joins nodes e and (e+1) % 4 and the
/// opposite local edge is e ^ 2.
///
///   3-------2
///   |       |
///   |       |
///   0-------1
namespace ref_quad {
inline constexpr int n_nodes = 4;
inline constexpr int n_faces = 4;
inline constexpr std::array<std::array<int, 2>, 4> face_nodes = {{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
}  // namespace ref_quad

/// Reference hex, binary numbering v = i + 2j + 4k (bit 0: x, bit 1: y, bit 2: z).
///
///        6-------7
///       /|      /|         z
///      4-------5 |         |  y
///      | 2-----|-3         | /
///      |/      |/          |/
///      0-------1           +----- x
///
/// Local faces 0..5 are x-, x+, y-, y+, z-, z+; the opposite local face is lf ^ 1. Each
/// face's nodes go counter-clockwise seen from outside (right-hand normal points out).
namespace ref_hex {
inline constexpr int n_nodes = 8;
inline constexpr int n_faces = 6;
inline constexpr std::array<std::array<int, 4>, 6> face_nodes = {{
    {0, 4, 6, 2},  // x-
    {1, 3, 7, 5},  // x+
    {0, 1, 5, 4},  // y-
    {2, 6, 7, 3},  // y+
    {0, 2, 3, 1},  // z-
    {4, 5, 7, 6},  // z+
}};
/// The 12 edges: four along x, four along y, four along z.
inline constexpr std::array<std::array<int, 2>, 12> edges = {{{0, 1},
                                                              {2, 3},
                                                              {4, 5},
                                                              {6, 7},
                                                              {0, 2},
                                                              {1, 3},
                                                              {4, 6},
                                                              {5, 7},
                                                              {0, 4},
                                                              {1, 5},
                                                              {2, 6},
                                                              {3, 7}}};
/// binary node b is VTK_HEXAHEDRON node vtk_of_binary[b] (the table is its own inverse).
inline constexpr std::array<int, 8> vtk_of_binary = {0, 1, 3, 2, 4, 5, 7, 6};
}  // namespace ref_hex

}  // namespace hexadapt
