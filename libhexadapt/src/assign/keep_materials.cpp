#include "hexadapt/assign/keep_materials.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

// How many cells of the grid's mean volume material m's input volume fills, at least one.
template <class M>
index_t cells_for(const M& mesh, const Fractions& f, int m) {
  double material = 0, total = 0;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const double v = mesh.cell_volume(c);
    material += f(c, m) * v;
    total += v;
  }
  const double mean = total / static_cast<double>(mesh.n_cells());
  return std::max<index_t>(1, static_cast<index_t>(std::llround(material / mean)));
}

// Material m's cells, most present first (ties to the lowest id), where it is present.
std::vector<CellId> by_presence(const Fractions& f, int m) {
  std::vector<CellId> cells;
  for (CellId c : id_range<CellId>(f.n_cells()))
    if (f(c, m) > 0) cells.push_back(c);
  std::stable_sort(cells.begin(), cells.end(),
                   [&](CellId a, CellId b) { return f(a, m) > f(b, m); });
  return cells;
}

}  // namespace

template <class M>
std::vector<KeptMaterial> keep_vanished_materials(const M& mesh, const Fractions& fractions,
                                                  Labels& labels) {
  std::vector<index_t> count(static_cast<std::size_t>(fractions.n_materials()), 0);
  for (int m : labels) ++count[static_cast<std::size_t>(m)];
  std::vector<char> vanished(count.size(), 0);
  for (int m = 0; m < fractions.n_materials(); ++m)
    vanished[static_cast<std::size_t>(m)] = count[static_cast<std::size_t>(m)] == 0;
  std::vector<KeptMaterial> kept;
  for (int m = 0; m < fractions.n_materials(); ++m) {
    if (!vanished[static_cast<std::size_t>(m)]) continue;
    const index_t want = cells_for(mesh, fractions, m);
    KeptMaterial k{m, 0};
    for (CellId c : by_presence(fractions, m)) {
      if (k.cells == want) break;
      const auto from = static_cast<std::size_t>(labels[c]);
      if (vanished[from] || count[from] <= 1) continue;  // kept for another, or its last cell
      --count[from];
      ++count[static_cast<std::size_t>(m)];
      labels[c] = m;
      ++k.cells;
    }
    if (k.cells > 0) kept.push_back(k);
  }
  return kept;
}

template std::vector<KeptMaterial> keep_vanished_materials(const QuadMesh&, const Fractions&,
                                                           Labels&);
template std::vector<KeptMaterial> keep_vanished_materials(const HexMesh&, const Fractions&,
                                                           Labels&);

}  // namespace hexadapt::assign
