#include "hexadapt/assign/cost.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
IdVector<CellId, double> cell_volumes(const M& mesh, const dist::Communicator& comm) {
  IdVector<CellId, double> v(static_cast<std::size_t>(mesh.n_cells()), 0.0);
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    v[c] = std::abs(mesh.cell_volume(c));
  });
  // Volumes within 1e-7 of each other (sorted, each group anchored at its smallest) weigh
  // exactly the smallest: cells of one size in exact arithmetic then weigh the same in any
  // unit and place, so ties between configurations of equal cost do not follow the last bits
  // of the coordinates (a grid moved 1e6 away, or at 1e20, changed two cells of the triple
  // point before). The costs move by at most 1e-7 of a cell's volume. The groups are those of
  // the distinct volumes of every rank, so a cell weighs the same whatever the ranks hold.
  const auto distinct = [](std::vector<double> x) {
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
    return x;
  };
  const std::vector<double> values =
      distinct(dist::all_gather_values(comm, distinct({v.begin(), v.end()})));
  std::vector<double> anchors(values.size());
  double anchor = -1;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (anchor < 0 || values[i] > anchor * (1 + 1e-7)) anchor = values[i];
    anchors[i] = anchor;
  }
  for (double& x : v)
    x = anchors[static_cast<std::size_t>(std::lower_bound(values.begin(), values.end(), x) -
                                         values.begin())];
  return v;
}

double assignment_cost(const Fractions& fractions, const IdVector<CellId, double>& volumes,
                       const CellMaterials& labels) {
  double sum = 0;
  for (CellId c : id_range<CellId>(fractions.n_cells()))
    sum += cell_cost(fractions, volumes, c, labels[c]);
  return sum;
}

template IdVector<CellId, double> cell_volumes(const QuadMesh&, const dist::Communicator&);
template IdVector<CellId, double> cell_volumes(const HexMesh&, const dist::Communicator&);

}  // namespace hexadapt::assign
