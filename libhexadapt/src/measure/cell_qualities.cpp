// Per-cell scaled Jacobian and shape straight from file data, so that meshes the kernels
// refuse are still measured.
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel_progress.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/quality/scaled_jacobian.h"
#include "hexadapt/quality/shape.h"

namespace hexadapt {

namespace {

template <std::size_t N>
std::array<Vec3, N> corners(const io::MeshData& data, std::size_t c) {
  std::array<Vec3, N> p;
  for (std::size_t k = 0; k < N; ++k) p[k] = data.points[data.cells[c * N + k].idx()];
  return p;
}

}  // namespace

CellQualities cell_qualities(const io::MeshData& data, const Progress& progress, double from,
                             double to) {
  const index_t n_points = data.n_points();
  for (std::size_t i = 0; i < data.cells.size(); ++i) {
    const NodeId n = data.cells[i];
    if (!n.valid() || n.value() >= n_points)
      throw InputError(
          "", "cell " + std::to_string(i / static_cast<std::size_t>(data.nodes_per_cell())),
          "refers to node " + std::to_string(n.value()) + " but there are " +
              std::to_string(n_points) + " points");
  }
  CellQualities q;
  const auto n = static_cast<std::size_t>(data.n_cells());
  q.scaled_jacobian.resize(n);
  q.shape.resize(n);
  auto one_cell = [&](std::int64_t i) {
    const auto c = static_cast<std::size_t>(i);
    if (data.dim == 3) {
      const auto p = corners<8>(data, c);
      q.scaled_jacobian[c] = hex_scaled_jacobian(p);
      q.shape[c] = hex_shape(p);
    } else {
      const auto p = corners<4>(data, c);
      q.scaled_jacobian[c] = quad_scaled_jacobian(p);
      q.shape[c] = quad_shape(p);
    }
  };
  parallel_for_progress(data.n_cells(), progress, "quality", one_cell, from, to);
  return q;
}

}  // namespace hexadapt
