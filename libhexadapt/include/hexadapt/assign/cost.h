// The cost of an assignment, the paper's eq. (4): sum over cells of
// |1 - ma_{va(c)}(c)| * Vol(c), with each cell's own (unsigned) volume. It measures how much
// volume is given to a material the fractions did not put there.
#pragma once

#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

/// |cell_volume| of every cell (parallel), volumes within 1e-7 of each other made equal
/// (cost.cpp). On a block of a distributed mesh, every rank calls it with its block.
template <class M>
IdVector<CellId, double> cell_volumes(const M& mesh,
                                      const dist::Communicator& comm = dist::serial());

inline double cell_cost(const Fractions& fractions, const IdVector<CellId, double>& volumes,
                        CellId c, int m) {
  return (1.0 - fractions(c, m)) * volumes[c];
}

/// eq. (4) summed over every cell, in cell order.
double assignment_cost(const Fractions& fractions, const IdVector<CellId, double>& volumes,
                       const CellMaterials& labels);

}  // namespace hexadapt::assign
