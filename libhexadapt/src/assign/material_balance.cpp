#include "hexadapt/assign/material_balance.h"

#include <cmath>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
std::vector<MaterialBalance> material_balance(const M& mesh, const Fractions& fractions,
                                              const CellMaterials& labels,
                                              const dist::Distribution& where) {
  const auto n = static_cast<std::size_t>(fractions.n_materials());
  std::vector<MaterialBalance> out(n);
  // Exact sums: the same figures at any thread or rank count.
  ExactSum domain_sum;
  std::vector<ExactSum> input(n), assigned(n);
  for (CellId c : IdRange<CellId>(where.block.owned_cell_first, where.block.owned_cell_end)) {
    const double v = std::abs(mesh.cell_volume(c));
    domain_sum.add(v);
    for (std::size_t m = 0; m < n; ++m) input[m].add(fractions(c, static_cast<int>(m)) * v);
    const auto m = static_cast<std::size_t>(labels[c]);
    assigned[m].add(v);
    ++out[m].assigned_cells;
  }
  const double domain = dist::exact_sum(where.comm, domain_sum);
  for (std::size_t m = 0; m < n; ++m) {
    out[m].input_volume = dist::exact_sum(where.comm, input[m]);
    out[m].assigned_volume = dist::exact_sum(where.comm, assigned[m]);
    out[m].assigned_cells = dist::sum_in_rank_order(where.comm, out[m].assigned_cells);
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
