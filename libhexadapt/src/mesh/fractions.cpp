#include "hexadapt/mesh/fractions.h"

#include <algorithm>
#include <utility>

#include "hexadapt/core/parallel.h"

namespace hexadapt {

Fractions::Fractions(index_t n_cells, std::vector<std::string> names)
    : n_cells_(n_cells),
      names_(std::move(names)),
      data_(static_cast<std::size_t>(n_cells) * names_.size(), 0.0) {}

int Fractions::find(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  return it == names_.end() ? -1 : static_cast<int>(it - names_.begin());
}

int Fractions::majority(CellId c) const {
  int best = 0;
  for (int m = 1; m < n_materials(); ++m)
    if ((*this)(c, m) > (*this)(c, best)) best = m;
  return best;
}

bool Fractions::is_pure(CellId c) const {
  return (*this)(c, majority(c)) >= 1.0;
}

CellMaterials majority_materials(const Fractions& fractions) {
  CellMaterials m(static_cast<std::size_t>(fractions.n_cells()), 0);
  parallel_for(fractions.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    m[c] = fractions.majority(c);
  });
  return m;
}

}  // namespace hexadapt
