#include "hexadapt/assign/cost.h"

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
  return v;
}

double assignment_cost(const Fractions& fractions, const IdVector<CellId, double>& volumes,
                       const Labels& labels) {
  double sum = 0;
  for (CellId c : id_range<CellId>(fractions.n_cells()))
    sum += cell_cost(fractions, volumes, c, labels[c]);
  return sum;
}

template IdVector<CellId, double> cell_volumes(const QuadMesh&);
template IdVector<CellId, double> cell_volumes(const HexMesh&);

}  // namespace hexadapt::assign
