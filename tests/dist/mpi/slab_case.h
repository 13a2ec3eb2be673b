// What the MPI tests share: the ranks, a structured grid's slab as a rank holds it, a grid of many
// cell shapes.
#pragma once

#include <array>
#include <random>

#include "hexadapt/dist/block.h"
#include "hexadapt/dist/mpi_communicator.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::test {

// Gathers in rounds of 1000 bytes over all ranks: the larger gathers here take several rounds,
// each rank's part split unevenly (the tools' default, 256 MiB, is covered by the tool test).
inline const dist::Communicator& world() {
  static const dist::MpiCommunicator comm(1000);
  return comm;
}

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

/// A grid of `cells` with its nodes moved at random (cells of many volumes), the same on
/// every rank.
template <class M>
M jittered_grid(const std::array<int, 3>& cells, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.15, 0.15);
  std::vector<Vec3> points;
  const int nz = M::dim == 3 ? cells[2] : 0;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= cells[1]; ++j)
      for (int i = 0; i <= cells[0]; ++i) {
        Vec3 p(i + shift(rng), j + shift(rng), M::dim == 3 ? k + shift(rng) : 0.0);
        points.push_back(p);
      }
  if constexpr (M::dim == 3)
    return make_hex_grid(cells[0], cells[1], cells[2], std::move(points));
  else
    return make_quad_grid(cells[0], cells[1], std::move(points));
}

}  // namespace hexadapt::test
