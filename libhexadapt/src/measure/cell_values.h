// Helpers of the measure reports over file data: checking node ids, the corners and centroid
// of one cell.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/mesh/unit_frame.h"

namespace hexadapt {

/// Throws InputError naming the first cell that refers to a missing node.
inline void check_node_ids(const io::MeshData& data) {
  const index_t n_points = data.n_points();
  for (std::size_t i = 0; i < data.cells.size(); ++i) {
    const NodeId n = data.cells[i];
    if (!n.valid() || n.value() >= n_points)
      throw InputError(
          "", "cell " + std::to_string(i / static_cast<std::size_t>(data.nodes_per_cell())),
          "refers to node " + std::to_string(n.value()) + " but there are " +
              std::to_string(n_points) + " points");
  }
}

/// The N corner points of cell c (kernel order; N = 4 for quads, 8 for hexes).
template <std::size_t N>
std::array<Vec3, N> corners(const io::MeshData& data, std::size_t c) {
  std::array<Vec3, N> p;
  for (std::size_t k = 0; k < N; ++k) p[k] = data.points[data.cells[c * N + k].idx()];
  return p;
}

/// The corners of cell c scaled by the power of two, 2^-`*exponent`, that brings the cell's
/// largest coordinate extent into [1, 2) (world lengths = local lengths x 2^exponent). The
/// scaling is exact, so measures taken there are those of the cell as given, to the last bit,
/// but neither underflow nor overflow at any unit (a cell of 1e-300 has squared edges of
/// 1e-600). Distinct corners are at most 2^53 extents from 0, so nothing overflows.
template <std::size_t N>
std::array<Vec3, N> local_corners(const io::MeshData& data, std::size_t c, int* exponent) {
  std::array<Vec3, N> p = corners<N>(data, c);
  double extent = 0;
  for (const Vec3& x : p) extent = std::max(extent, (x - p[0]).cwiseAbs().maxCoeff());
  const UnitFrame scale{Vec3::Zero(), unit_exponent(extent)};
  *exponent = scale.exponent;
  for (Vec3& x : p) x = scale.to_local(x);
  return p;
}

/// The points and cells of `data` in `frame` (no arrays).
inline io::MeshData geometry_in_frame(const io::MeshData& data, const UnitFrame& frame) {
  io::MeshData local;
  local.dim = data.dim;
  local.cells = data.cells;
  local.points.reserve(data.points.size());
  for (const Vec3& p : data.points) local.points.push_back(frame.to_local(p));
  return local;
}

/// The mean of cell c's corners.
inline Vec3 centroid(const io::MeshData& data, std::size_t c) {
  const auto npc = static_cast<std::size_t>(data.nodes_per_cell());
  Vec3 s = Vec3::Zero();
  for (std::size_t k = 0; k < npc; ++k) s += data.points[data.cells[c * npc + k].idx()];
  return s / double(npc);
}

}  // namespace hexadapt
