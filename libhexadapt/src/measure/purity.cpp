// Purity: every cell holds one material. A `material` array must hold integer indices, not
// negative and, when fraction arrays name the materials, below their number. Fraction
// arrays (vf_*) tell how many cells are still mixed. On a part, the owned cells count.
#include "purity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "rank_figures.h"

namespace hexadapt {

namespace {

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

void count_mixed(const io::MeshData& data, const PartIds& ids, const QualityReportOptions& options,
                 PurityReport& r) {
  std::vector<const io::DataArray*> fractions;
  for (const auto& a : data.cell_data)
    if (a.n_components == 1 && starts_with(a.name, options.fraction_prefix)) {
      fractions.push_back(&a);
      r.fraction_arrays.push_back(a.name);
    }
  if (fractions.empty()) return;
  for (std::size_t c = 0; c < static_cast<std::size_t>(ids.owned_cells(data.n_cells())); ++c) {
    double largest = 0;
    for (const auto* a : fractions) largest = std::max(largest, a->values[c]);
    if (largest >= 1 - options.pure_tolerance) continue;
    if (++r.mixed_cells <= options.max_listed) r.first_mixed.push_back(CellId(ids.cell(c)));
  }
}

void check_material(const io::MeshData& data, const PartIds& ids,
                    const QualityReportOptions& options, PurityReport& r) {
  const io::DataArray* m = data.find_cell_array(options.material_array);
  if (!m) return;
  if (m->n_components != 1)
    throw InputError(
        "", "cell array '" + m->name + "'",
        "expected one component (a material index), found " + std::to_string(m->n_components));
  r.has_material = true;
  const double n_materials = r.fraction_arrays.empty() ? std::numeric_limits<double>::infinity()
                                                       : double(r.fraction_arrays.size());
  for (std::size_t c = 0; c < static_cast<std::size_t>(ids.owned_cells(data.n_cells())); ++c) {
    const double v = m->values[c];
    if (v >= 0 && v < n_materials && v == std::floor(v)) continue;
    if (++r.invalid_material_cells <= options.max_listed)
      r.first_invalid.push_back(CellId(ids.cell(c)));
  }
}

}  // namespace

PurityReport measure_purity(const dist::Communicator& comm, const io::MeshData& data,
                            const PartIds& ids, const QualityReportOptions& options) {
  PurityReport r;
  count_mixed(data, ids, options, r);
  check_material(data, ids, options, r);
  r.mixed_cells = static_cast<index_t>(total(comm, r.mixed_cells));
  r.invalid_material_cells = static_cast<index_t>(total(comm, r.invalid_material_cells));
  r.first_mixed = first_of_ranks(comm, std::move(r.first_mixed), options.max_listed);
  r.first_invalid = first_of_ranks(comm, std::move(r.first_invalid), options.max_listed);
  return r;
}

}  // namespace hexadapt
