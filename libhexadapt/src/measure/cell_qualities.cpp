// Per-cell scaled Jacobian and shape straight from file data, so that meshes the kernels
// refuse are still measured.
#include "cell_values.h"
#include "hexadapt/core/parallel_progress.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/quality/scaled_jacobian.h"
#include "hexadapt/quality/shape.h"

namespace hexadapt {

CellQualities cell_qualities(const io::MeshData& data, const Progress& progress, double from,
                             double to) {
  check_node_ids(data);
  CellQualities q;
  const auto n = static_cast<std::size_t>(data.n_cells());
  q.scaled_jacobian.resize(n);
  q.shape.resize(n);
  auto one_cell = [&](std::int64_t i) {
    const auto c = static_cast<std::size_t>(i);
    int exponent = 0;  // shape measures do not depend on it
    if (data.dim == 3) {
      const auto p = local_corners<8>(data, c, &exponent);
      q.scaled_jacobian[c] = hex_scaled_jacobian(p);
      q.shape[c] = hex_shape(p);
    } else {
      const auto p = local_corners<4>(data, c, &exponent);
      q.scaled_jacobian[c] = quad_scaled_jacobian(p);
      q.shape[c] = quad_shape(p);
    }
  };
  parallel_for_progress(data.n_cells(), progress, "quality", one_cell, from, to);
  return q;
}

}  // namespace hexadapt
