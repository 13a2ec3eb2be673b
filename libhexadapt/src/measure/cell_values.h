// Helpers of the measure reports over file data: checking node ids, the corners and centroid
// of one cell, and the min / mean / max of per-cell values.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/quality_report.h"

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

/// The mean of cell c's corners.
inline Vec3 centroid(const io::MeshData& data, std::size_t c) {
  const auto npc = static_cast<std::size_t>(data.nodes_per_cell());
  Vec3 s = Vec3::Zero();
  for (std::size_t k = 0; k < npc; ++k) s += data.points[data.cells[c * npc + k].idx()];
  return s / double(npc);
}

/// Min, plain mean and max (all 0 when `v` is empty).
inline QualityStats stats(const std::vector<double>& v) {
  QualityStats s;
  if (v.empty()) return s;
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  double sum = 0;  // serial, in cell order: the same bytes whatever the thread count
  for (double x : v) sum += x;
  s.mean = sum / double(v.size());
  return s;
}

}  // namespace hexadapt
