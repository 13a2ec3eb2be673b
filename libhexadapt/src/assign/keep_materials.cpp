#include "hexadapt/assign/keep_materials.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/assign/material_balance.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

// A cell where a vanished material is present: its fraction there, global id and label.
struct Candidate {
  double presence;
  std::int64_t cell;
  int label;
};

// Material m's cells over every rank, where it is present, most present first (ties to the
// lowest global id): each rank sends the cells it owns.
std::vector<Candidate> by_presence(const Fractions& f, const CellMaterials& labels, int m,
                                   const dist::Distribution& where) {
  std::vector<double> presence;
  std::vector<std::int64_t> cell;
  std::vector<int> label;
  const dist::Block& b = where.block;
  for (index_t k = b.owned_cell_first; k < b.owned_cell_end; ++k) {
    const CellId c(k);
    if (f(c, m) <= 0) continue;
    presence.push_back(f(c, m));
    cell.push_back(b.global(c));
    label.push_back(labels[c]);
  }
  presence = dist::all_gather_values(where.comm, presence);
  cell = dist::all_gather_values(where.comm, cell);
  label = dist::all_gather_values(where.comm, label);
  std::vector<Candidate> out;
  for (std::size_t i = 0; i < cell.size(); ++i) out.push_back({presence[i], cell[i], label[i]});
  std::sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y) {
    return x.presence > y.presence || (x.presence == y.presence && x.cell < y.cell);
  });
  return out;
}

}  // namespace

template <class M>
std::vector<KeptMaterial> keep_vanished_materials(const M& mesh, const Fractions& fractions,
                                                  CellMaterials& labels,
                                                  const dist::Distribution& where) {
  const std::vector<MaterialBalance> balance = material_balance(mesh, fractions, labels, where);
  std::vector<index_t> count;
  std::vector<char> vanished;
  index_t n_cells = 0;  // of the whole grid
  for (const MaterialBalance& b : balance) {
    count.push_back(b.assigned_cells);
    vanished.push_back(b.vanished());
    n_cells += b.assigned_cells;
  }
  std::vector<KeptMaterial> kept;
  for (int m = 0; m < fractions.n_materials(); ++m) {
    if (!vanished[static_cast<std::size_t>(m)]) continue;
    // As many cells of the grid's mean volume as the material's input volume fills.
    const double share = balance[static_cast<std::size_t>(m)].input_share;
    const index_t want = std::max<index_t>(
        1, static_cast<index_t>(std::llround(share * static_cast<double>(n_cells))));
    KeptMaterial k{m, 0};
    for (const Candidate& c : by_presence(fractions, labels, m, where)) {
      if (k.cells == want) break;
      const auto from = static_cast<std::size_t>(c.label);
      if (vanished[from] || count[from] <= 1) continue;  // kept for another, or its last cell
      --count[from];
      ++count[static_cast<std::size_t>(m)];
      const CellId held = where.block.local_cell(c.cell);
      if (held.valid()) labels[held] = m;
      ++k.cells;
    }
    if (k.cells > 0) kept.push_back(k);
  }
  return kept;
}

template <class M>
std::vector<KeptMaterial> keep_vanished_materials(const M& mesh, const Fractions& fractions,
                                                  CellMaterials& labels) {
  return keep_vanished_materials(mesh, fractions, labels, dist::Distribution::whole(mesh));
}

template std::vector<KeptMaterial> keep_vanished_materials(const QuadMesh&, const Fractions&,
                                                           CellMaterials&,
                                                           const dist::Distribution&);
template std::vector<KeptMaterial> keep_vanished_materials(const HexMesh&, const Fractions&,
                                                           CellMaterials&,
                                                           const dist::Distribution&);
template std::vector<KeptMaterial> keep_vanished_materials(const QuadMesh&, const Fractions&,
                                                           CellMaterials&);
template std::vector<KeptMaterial> keep_vanished_materials(const HexMesh&, const Fractions&,
                                                           CellMaterials&);

}  // namespace hexadapt::assign
