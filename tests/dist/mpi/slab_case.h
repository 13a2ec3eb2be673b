// What the MPI tests share: a structured grid's slab as a rank holds it.
#pragma once

#include <array>

#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::test {

/// The part of `whole` (a structured grid of `cells`) and of its fractions that `slab` holds.
template <class M>
std::pair<M, Fractions> held_part(const M& whole, const Fractions& fractions,
                                  const std::array<int, 3>& cells, const dist::Slab& slab) {
  const dist::Block& b = slab.block;
  std::vector<Vec3> points;
  for (index_t n = 0; n < b.held_nodes; ++n)
    points.push_back(whole.point(NodeId(static_cast<index_t>(b.node_offset + n))));
  Fractions f(b.held_cells, fractions.names());
  for (CellId c : id_range<CellId>(b.held_cells))
    for (int m = 0; m < f.n_materials(); ++m)
      f(c, m) = fractions(CellId(static_cast<index_t>(b.global(c))), m);
  if constexpr (M::dim == 3)
    return {make_hex_grid(cells[0], cells[1], slab.held[2], std::move(points)), std::move(f)};
  else
    return {make_quad_grid(cells[0], slab.held[1], std::move(points)), std::move(f)};
}

}  // namespace hexadapt::test
