#include "hexadapt/assign/cost.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
IdVector<CellId, double> cell_volumes(const M& mesh) {
  IdVector<CellId, double> v(static_cast<std::size_t>(mesh.n_cells()), 0.0);
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    v[c] = std::abs(mesh.cell_volume(c));
  });
  // Volumes within 1e-7 of each other (sorted, each group anchored at its smallest) weigh
  // exactly the smallest: cells of one size in exact arithmetic then weigh the same in any
  // unit and place, so ties between configurations of equal cost do not follow the last bits
  // of the coordinates (a grid moved 1e6 away, or at 1e20, changed two cells of the triple
  // point before). The costs move by at most 1e-7 of a cell's volume.
  std::vector<std::pair<double, index_t>> sorted;
  sorted.reserve(v.size());
  for (CellId c : id_range<CellId>(mesh.n_cells())) sorted.emplace_back(v[c], c.value());
  std::sort(sorted.begin(), sorted.end());
  double anchor = -1;
  for (const auto& [x, i] : sorted) {
    if (anchor < 0 || x > anchor * (1 + 1e-7)) anchor = x;
    v[CellId(i)] = anchor;
  }
  return v;
}

double assignment_cost(const Fractions& fractions, const IdVector<CellId, double>& volumes,
                       const CellMaterials& labels) {
  double sum = 0;
  for (CellId c : id_range<CellId>(fractions.n_cells()))
    sum += cell_cost(fractions, volumes, c, labels[c]);
  return sum;
}

template IdVector<CellId, double> cell_volumes(const QuadMesh&);
template IdVector<CellId, double> cell_volumes(const HexMesh&);

}  // namespace hexadapt::assign
