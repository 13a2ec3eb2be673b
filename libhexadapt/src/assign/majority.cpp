#include "hexadapt/assign/majority.h"

#include "hexadapt/core/parallel.h"

namespace hexadapt::assign {

Labels majority_assignment(const Fractions& fractions) {
  Labels labels(static_cast<std::size_t>(fractions.n_cells()), 0);
  parallel_for(fractions.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    labels[c] = fractions.majority(c);
  });
  return labels;
}

}  // namespace hexadapt::assign
