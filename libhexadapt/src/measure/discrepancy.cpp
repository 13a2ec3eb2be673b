// Per-cell discrepancy (paper eq. 5) and volume balance per material.
#include "hexadapt/measure/discrepancy.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "hexadapt/core/error.h"
#include "hexadapt/measure/imprint.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

double MaterialVolume::volume_error() const {
  return input != 0 ? (output - input) / input : std::numeric_limits<double>::quiet_NaN();
}

bool DiscrepancyReport::passed() const {
  for (const auto& m : materials)
    if (std::abs(m.volume_error()) > max_volume_error) return false;
  return true;
}

namespace {

int worst_material(const std::vector<MaterialVolume>& materials) {
  int worst = -1;
  double largest = -1;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const double e = std::abs(materials[m].volume_error());  // NaN (no input) never wins
    if (e > largest) {
      largest = e;
      worst = static_cast<int>(m);
    }
  }
  return worst;
}

}  // namespace

DiscrepancyReport discrepancy(const Imprint& im, const Fractions& f,
                              const DiscrepancyOptions& options) {
  if (!(options.max_volume_error >= 0)) throw OptionError("max_volume_error must be >= 0");
  if (f.n_cells() != im.n_cells || f.n_materials() != im.n_materials)
    throw InputError({}, {},
                     "discrepancy: " + std::to_string(f.n_cells()) + " cells and " +
                         std::to_string(f.n_materials()) + " materials in the fractions, " +
                         std::to_string(im.n_cells) + " and " + std::to_string(im.n_materials) +
                         " in the imprint");
  DiscrepancyReport r;
  r.per_cell.assign(static_cast<std::size_t>(im.n_cells), 0.0);
  r.materials.resize(static_cast<std::size_t>(im.n_materials));
  for (int m = 0; m < im.n_materials; ++m) {
    auto& mv = r.materials[static_cast<std::size_t>(m)];
    mv.name = f.names()[static_cast<std::size_t>(m)];
    mv.output = im.output_volume[static_cast<std::size_t>(m)];
  }
  for (CellId c : id_range<CellId>(im.n_cells)) {
    const double vc = im.cell_volume[c.idx()];
    double d = 0;
    for (int m = 0; m < im.n_materials; ++m) {
      const double want = f(c, m) * vc, got = im.at(c.value(), m);
      d += std::abs(got - want);
      r.materials[static_cast<std::size_t>(m)].input += want;
      r.materials[static_cast<std::size_t>(m)].imprinted += got;
    }
    r.per_cell[c.idx()] = d;
    r.total += d;
    r.input_volume += vc;
    if (d > r.max_cell) {
      r.max_cell = d;
      r.max_cell_id = c;
    }
  }
  r.relative = r.input_volume > 0 ? r.total / r.input_volume : 0;
  r.max_volume_error = options.max_volume_error;
  r.volume_exponent = im.volume_exponent;
  r.worst_material = worst_material(r.materials);
  return r;
}

std::string discrepancy_json(const DiscrepancyReport& r) {
  nlohmann::ordered_json j;
  j["total"] = r.in_grid_units(r.total);
  j["relative"] = r.relative;
  j["input_volume"] = r.in_grid_units(r.input_volume);
  j["max_cell"] = {{"value", r.in_grid_units(r.max_cell)},
                   {"cell", r.max_cell_id.valid() ? nlohmann::ordered_json(r.max_cell_id.value())
                                                  : nlohmann::ordered_json(nullptr)}};
  auto mats = nlohmann::ordered_json::array();
  for (const auto& m : r.materials)
    mats.push_back({{"name", m.name},
                    {"input", r.in_grid_units(m.input)},
                    {"output", r.in_grid_units(m.output)},
                    {"imprinted", r.in_grid_units(m.imprinted)},
                    {"imprinted_minus_input", r.in_grid_units(m.imprinted - m.input)},
                    {"volume_error", m.volume_error()}});
  j["materials"] = mats;
  const auto* worst =
      r.worst_material >= 0 ? &r.materials[static_cast<std::size_t>(r.worst_material)] : nullptr;
  j["worst_volume_error"] =
      worst ? nlohmann::ordered_json{{"name", worst->name}, {"value", worst->volume_error()}}
            : nlohmann::ordered_json(nullptr);
  j["max_volume_error"] = r.max_volume_error;
  j["passed"] = r.passed();
  return j.dump();
}

}  // namespace hexadapt
