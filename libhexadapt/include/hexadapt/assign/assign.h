// The assignment stage (paper sec. 3): majority assignment, then manifold correction.
// This is what hexadapt-assign runs; the steps are also available one by one
// (majority.h, manifold.h, enumerate.h, correction.h).
#pragma once

#include "hexadapt/assign/correction.h"
#include "hexadapt/assign/majority.h"
#include "hexadapt/assign/material_balance.h"

namespace hexadapt::assign {

struct AssignResult {
  Labels majority;              ///< eq. (2), before correction
  CorrectionResult correction;  ///< labels: the final assignment, with statistics
  PhaseTimes times;             ///< majority, then the correction's phases
  /// Per material, input and assigned volumes of the final assignment (in the grid's units;
  /// shares computed before, so a grid of 1e-300 still has them).
  std::vector<MaterialBalance> balance;
};

template <class M>
AssignResult assign_materials(const M& mesh, const Fractions& fractions,
                              const CorrectionOptions& options = {});

}  // namespace hexadapt::assign
