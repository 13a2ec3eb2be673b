// Private to generate/: the cells of an io::MeshData as point arrays, their volume and scaled
// Jacobian, without building a mesh kernel (a 128^3 grid is sampled in well under the time
// the half-face kernel takes to build).
#pragma once

#include <array>
#include <cstddef>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt::generate::detail {

/// The corners of cell c in kernel order (ccw quad, binary hex).
template <int D>
std::array<Vec3, (1 << D)> cell_corners(const io::MeshData& d, std::size_t c) {
  std::array<Vec3, (1 << D)> p;
  for (std::size_t v = 0; v < p.size(); ++v) p[v] = d.points[d.cells[c * p.size() + v].idx()];
  return p;
}

inline double cell_volume(const io::MeshData& d, std::size_t c) {
  return d.dim == 3 ? hex_volume(cell_corners<3>(d, c)) : quad_area(cell_corners<2>(d, c));
}

inline double cell_quality(const io::MeshData& d, std::size_t c) {
  return d.dim == 3 ? hex_scaled_jacobian(cell_corners<3>(d, c))
                    : quad_scaled_jacobian(cell_corners<2>(d, c));
}

}  // namespace hexadapt::generate::detail
