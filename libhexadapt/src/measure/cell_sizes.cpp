// Per-cell edge lengths and time-step length straight from file data (see cell_sizes.h).
#include "cell_sizes.h"

#include <cmath>

#include "cell_values.h"
#include "hexadapt/core/parallel_progress.h"

namespace hexadapt {

CellSizes cell_sizes(const io::MeshData& data, const Progress& progress, double from, double to) {
  check_node_ids(data);
  CellSizes s;
  const auto n = static_cast<std::size_t>(data.n_cells());
  s.edges.resize(n);
  s.time_step.resize(n);
  auto one_cell = [&](std::int64_t i) {
    const auto c = static_cast<std::size_t>(i);
    int e = 0;
    if (data.dim == 3) {
      const auto p = local_corners<8>(data, c, &e);
      s.edges[c] = hex_edge_lengths(p);
      s.time_step[c] = hex_time_step_length(p);
    } else {
      const auto p = local_corners<4>(data, c, &e);
      s.edges[c] = quad_edge_lengths(p);
      s.time_step[c] = quad_time_step_length(p);
    }
    // Back to the grid's units.
    for (double* x : {&s.edges[c].min, &s.edges[c].max, &s.edges[c].mean, &s.time_step[c]})
      *x = std::ldexp(*x, e);
  };
  parallel_for_progress(data.n_cells(), progress, "size", one_cell, from, to);
  return s;
}

}  // namespace hexadapt
