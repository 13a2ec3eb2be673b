// The small cell-complex interface QuadMesh and HexMesh both provide, and helpers written
// once against it (DESIGN sec. 3: one source for 2D and 3D).
//
// A type M is a cell complex when it has:
//   M::dim, M::nodes_per_cell, M::faces_per_cell, M::nodes_per_face
//   n_cells(), n_nodes()
//   cell_nodes(CellId)         the cell's nodes (ccw quad / binary hex order)
//   face_nodes(CellId, lf)     nodes of local face lf (an edge in 2D), outward orientation
//   neighbour(CellId, lf)      the cell across local face lf, invalid on the boundary
//   node_cells(NodeId)         cells around a node, increasing ids
//   point(NodeId), set_point(NodeId, Vec3)
//   cell_volume(CellId)        signed area / volume
//   cell_quality(CellId)       signed scaled Jacobian in [-1, 1]
// Algorithms are templates over M, instantiated for QuadMesh and HexMesh only.
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <variant>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt {

template <class M>
inline constexpr bool is_cell_complex_v =
    std::is_same_v<M, QuadMesh> || std::is_same_v<M, HexMesh>;

/// A mesh read from a file: 2D or 3D is decided by its cell type.
using AnyMesh = std::variant<QuadMesh, HexMesh>;

/// Average of the cell's corner points.
template <class M>
Vec3 cell_centroid(const M& mesh, CellId c) {
  Vec3 s = Vec3::Zero();
  for (NodeId n : mesh.cell_nodes(c)) s += mesh.point(n);
  return s / M::nodes_per_cell;
}

/// Smallest scaled Jacobian over all cells (1 for an empty mesh), block by block on the
/// library's threads (a minimum is the same in any order).
template <class M>
double min_quality(const M& mesh) {
  constexpr std::int64_t block = 4096;
  const std::int64_t n = mesh.n_cells();
  std::vector<double> least(static_cast<std::size_t>((n + block - 1) / block), 1.0);
  parallel_for(static_cast<std::int64_t>(least.size()), [&](std::int64_t b) {
    const std::int64_t end = std::min<std::int64_t>(n, (b + 1) * block);
    double q = 1.0;
    for (std::int64_t i = b * block; i < end; ++i) q = std::min(q, mesh.cell_quality(CellId(i)));
    least[static_cast<std::size_t>(b)] = q;
  });
  double q = 1.0;
  for (double l : least) q = std::min(q, l);
  return q;
}

}  // namespace hexadapt
