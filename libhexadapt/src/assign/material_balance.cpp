#include "hexadapt/assign/material_balance.h"

#include <cmath>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
std::vector<MaterialBalance> material_balance(const M& mesh, const Fractions& fractions,
                                              const CellMaterials& labels) {
  std::vector<MaterialBalance> out(static_cast<std::size_t>(fractions.n_materials()));
  double domain = 0;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {  // serial: the same sums at any thread count
    const double v = std::abs(mesh.cell_volume(c));
    domain += v;
    for (int m = 0; m < fractions.n_materials(); ++m)
      out[static_cast<std::size_t>(m)].input_volume += fractions(c, m) * v;
    MaterialBalance& a = out[static_cast<std::size_t>(labels[c])];
    a.assigned_volume += v;
    ++a.assigned_cells;
  }
  for (MaterialBalance& b : out) b.input_share = domain > 0 ? b.input_volume / domain : 0;
  return out;
}

template std::vector<MaterialBalance> material_balance(const QuadMesh&, const Fractions&,
                                                       const CellMaterials&);
template std::vector<MaterialBalance> material_balance(const HexMesh&, const Fractions&,
                                                       const CellMaterials&);

}  // namespace hexadapt::assign
