#include "hexadapt/assign/assign.h"

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
AssignResult assign_materials(const M& mesh, const Fractions& fractions,
                              const CorrectionOptions& options) {
  AssignResult r;
  Timer t;
  r.majority = majority_assignment(fractions);
  r.times.emplace_back("majority", t.seconds());
  r.correction = correct_assignment(mesh, fractions, r.majority, options);
  for (const auto& phase : r.correction.times) r.times.push_back(phase);
  return r;
}

template AssignResult assign_materials(const QuadMesh&, const Fractions&, const CorrectionOptions&);
template AssignResult assign_materials(const HexMesh&, const Fractions&, const CorrectionOptions&);

}  // namespace hexadapt::assign
