// Purity: every cell holds one material. A `material` array must hold integer indices, not
// negative and, when fraction arrays name the materials, below their number. Fraction
// arrays (vf_*) tell how many cells are still mixed.
#include "purity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt {

namespace {

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

void count_mixed(const io::MeshData& data, const QualityReportOptions& options, PurityReport& r) {
  std::vector<const io::DataArray*> fractions;
  for (const auto& a : data.cell_data)
    if (a.n_components == 1 && starts_with(a.name, options.fraction_prefix)) {
      fractions.push_back(&a);
      r.fraction_arrays.push_back(a.name);
    }
  if (fractions.empty()) return;
  for (std::size_t c = 0; c < static_cast<std::size_t>(data.n_cells()); ++c) {
    double largest = 0;
    for (const auto* a : fractions) largest = std::max(largest, a->values[c]);
    if (largest >= 1 - options.pure_tolerance) continue;
    if (++r.mixed_cells <= options.max_listed) r.first_mixed.push_back(CellId(c));
  }
}

void check_material(const io::MeshData& data, const QualityReportOptions& options,
                    PurityReport& r) {
  const io::DataArray* m = data.find_cell_array(options.material_array);
  if (!m) return;
  if (m->n_components != 1)
    throw InputError(
        "", "cell array '" + m->name + "'",
        "expected one component (a material index), found " + std::to_string(m->n_components));
  r.has_material = true;
  const double n_materials = r.fraction_arrays.empty() ? std::numeric_limits<double>::infinity()
                                                       : double(r.fraction_arrays.size());
  for (std::size_t c = 0; c < m->values.size(); ++c) {
    const double v = m->values[c];
    if (v >= 0 && v < n_materials && v == std::floor(v)) continue;
    if (++r.invalid_material_cells <= options.max_listed) r.first_invalid.push_back(CellId(c));
  }
}

}  // namespace

PurityReport measure_purity(const io::MeshData& data, const QualityReportOptions& options) {
  PurityReport r;
  count_mixed(data, options, r);
  check_material(data, options, r);
  return r;
}

}  // namespace hexadapt
