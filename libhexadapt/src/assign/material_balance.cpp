#include "hexadapt/assign/material_balance.h"

#include <cmath>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
std::vector<MaterialBalance> material_balance(const M& mesh, const Fractions& fractions,
                                              const CellMaterials& labels,
                                              const dist::Distribution& where) {
  std::vector<MaterialBalance> out(static_cast<std::size_t>(fractions.n_materials()));
  double domain = 0;
  // serial: the same sums at any thread count
  for (CellId c : IdRange<CellId>(where.block.owned_cell_first, where.block.owned_cell_end)) {
    const double v = std::abs(mesh.cell_volume(c));
    domain += v;
    for (int m = 0; m < fractions.n_materials(); ++m)
      out[static_cast<std::size_t>(m)].input_volume += fractions(c, m) * v;
    MaterialBalance& a = out[static_cast<std::size_t>(labels[c])];
    a.assigned_volume += v;
    ++a.assigned_cells;
  }
  domain = dist::sum_in_rank_order(where.comm, domain);
  for (MaterialBalance& b : out) {
    b.input_volume = dist::sum_in_rank_order(where.comm, b.input_volume);
    b.assigned_volume = dist::sum_in_rank_order(where.comm, b.assigned_volume);
    b.assigned_cells = dist::sum_in_rank_order(where.comm, b.assigned_cells);
  }
  for (MaterialBalance& b : out) b.input_share = domain > 0 ? b.input_volume / domain : 0;
  return out;
}

template <class M>
std::vector<MaterialBalance> material_balance(const M& mesh, const Fractions& fractions,
                                              const CellMaterials& labels) {
  return material_balance(mesh, fractions, labels, dist::Distribution::whole(mesh));
}

template std::vector<MaterialBalance> material_balance(const QuadMesh&, const Fractions&,
                                                       const CellMaterials&);
template std::vector<MaterialBalance> material_balance(const HexMesh&, const Fractions&,
                                                       const CellMaterials&);
template std::vector<MaterialBalance> material_balance(const QuadMesh&, const Fractions&,
                                                       const CellMaterials&,
                                                       const dist::Distribution&);
template std::vector<MaterialBalance> material_balance(const HexMesh&, const Fractions&,
                                                       const CellMaterials&,
                                                       const dist::Distribution&);

}  // namespace hexadapt::assign
