#include "hexadapt/assign/keep_materials.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/assign/material_balance.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

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
                                                  CellMaterials& labels) {
  const std::vector<MaterialBalance> balance = material_balance(mesh, fractions, labels);
  std::vector<index_t> count;
  std::vector<char> vanished;
  for (const MaterialBalance& b : balance) {
    count.push_back(b.assigned_cells);
    vanished.push_back(b.vanished());
  }
  std::vector<KeptMaterial> kept;
  for (int m = 0; m < fractions.n_materials(); ++m) {
    if (!vanished[static_cast<std::size_t>(m)]) continue;
    // As many cells of the grid's mean volume as the material's input volume fills.
    const double share = balance[static_cast<std::size_t>(m)].input_share;
    const index_t want = std::max<index_t>(
        1, static_cast<index_t>(std::llround(share * static_cast<double>(mesh.n_cells()))));
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
                                                           CellMaterials&);
template std::vector<KeptMaterial> keep_vanished_materials(const HexMesh&, const Fractions&,
                                                           CellMaterials&);

}  // namespace hexadapt::assign
