// Structured constructors: Cartesian, rectilinear and curvilinear grids of quads or hexes.
//
// Cell (i, j[, k]) has id i + nx * (j + ny * k) and node (i, j[, k]) has id
// i + (nx + 1) * (j + (ny + 1) * k), as in VTK's structured data sets.
#pragma once

#include <array>
#include <vector>

#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt {

/// nx x ny unit-spaced (or `spacing`) quads from `origin`, in the z = origin.z() plane.
QuadMesh make_quad_grid(int nx, int ny, const Vec3& origin = Vec3::Zero(),
                        const Vec3& spacing = Vec3::Ones());
/// Rectilinear: node coordinates per axis, strictly increasing (sizes nx + 1, ny + 1).
QuadMesh make_quad_grid(const std::vector<double>& xs, const std::vector<double>& ys);
/// Curvilinear: nx x ny cells over the (nx + 1) * (ny + 1) given points, i fastest.
QuadMesh make_quad_grid(int nx, int ny, std::vector<Vec3> points);

HexMesh make_hex_grid(int nx, int ny, int nz, const Vec3& origin = Vec3::Zero(),
                      const Vec3& spacing = Vec3::Ones());
HexMesh make_hex_grid(const std::vector<double>& xs, const std::vector<double>& ys,
                      const std::vector<double>& zs);
HexMesh make_hex_grid(int nx, int ny, int nz, std::vector<Vec3> points);

/// The cells of a structured block with nx x ny (x nz) cells, node ids as above:
/// counter-clockwise quads when nz == 0, binary-order hexes otherwise; cell after cell,
/// 4 or 8 ids each, appended to `out` (the one source of this numbering).
void append_structured_cells(int nx, int ny, int nz, std::vector<NodeId>& out);

/// The same cells as arrays of node ids.
std::vector<std::array<NodeId, 4>> structured_quads(int nx, int ny);
std::vector<std::array<NodeId, 8>> structured_hexes(int nx, int ny, int nz);

}  // namespace hexadapt
