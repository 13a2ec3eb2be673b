// The same grid in another unit and place, for the tests of unit independence.
#pragma once

#include <utility>
#include <vector>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::test {

/// Every coordinate times `scale`, plus `offset` (in x and y, and z in 3D).
template <class M>
M scaled(const M& mesh, double scale, double offset = 0) {
  std::vector<Vec3> points;
  std::vector<typename M::CellNodes> cells;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    points.push_back(scale * mesh.point(v) + Vec3(offset, offset, M::dim == 3 ? offset : 0));
  for (CellId c : id_range<CellId>(mesh.n_cells())) cells.push_back(mesh.cell_nodes(c));
  return M(std::move(points), std::move(cells));
}

}  // namespace hexadapt::test
