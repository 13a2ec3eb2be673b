// Majority assignment: the initial virtual assignment of the paper's sec. 3.1, eq. (2).
//
// Every cell takes the material with the largest volume fraction; ties go to the lowest
// material index (the "first material examined" of the paper). The result is the starting
// point of the manifold correction (correction.h).
#pragma once

#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

/// A material index per cell (an index into Fractions::names()).
using Labels = IdVector<CellId, int>;

/// va(c) = argmax_m ma_m(c), ties to the lowest index.
Labels majority_assignment(const Fractions& fractions);

}  // namespace hexadapt::assign
