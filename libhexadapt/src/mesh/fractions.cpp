#include "hexadapt/mesh/fractions.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"

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

bool Fractions::is_pure(CellId c) const { return (*this)(c, majority(c)) >= 1.0; }

namespace {

// The array names `entries` stand for: an entry naming a cell array is that array, whatever
// it holds ("Volume Fraction for Body, Nose"); another one holding commas lists the names
// between them ("vf_a,vf_b"). Throws InputError naming the first missing array.
std::vector<std::string> requested_arrays(const io::MeshData& data,
                                          const std::vector<std::string>& entries,
                                          const std::string& file) {
  std::vector<std::string> out;
  for (const std::string& e : entries) {
    if (data.find_cell_array(e) || e.find(',') == std::string::npos) {
      out.push_back(e);
      continue;
    }
    std::size_t from = 0;
    for (std::size_t comma; (comma = e.find(',', from)) != std::string::npos; from = comma + 1)
      out.push_back(e.substr(from, comma - from));
    out.push_back(e.substr(from));
  }
  for (const std::string& n : out)
    if (!data.find_cell_array(n)) {
      std::string known;
      for (const auto& a : data.cell_data) known += (known.empty() ? "'" : ", '") + a.name + "'";
      throw InputError(file, "", "no cell array named '" + n + "' (the cell arrays: " +
                                     (known.empty() ? "none" : known) + ")");
    }
  return out;
}

// The arrays read and the material each fills; the void material, when named, is the
// remainder: appended after them, or in the place of the array of its name, which is then
// recomputed instead of read.
struct Selection {
  std::vector<const io::DataArray*> arrays;
  std::vector<int> material;  ///< per array, its material index
  int void_material = -1;     ///< its material index, -1 when none
};

Selection fraction_arrays(const io::MeshData& data, const FractionOptions& options,
                          std::vector<std::string>& names, const std::string& file) {
  Selection s;
  if (options.arrays.empty()) {
    for (const auto& a : data.cell_data)
      if (a.name.size() > 3 && a.name.compare(0, 3, "vf_") == 0) {
        s.arrays.push_back(&a);
        names.push_back(a.name.substr(3));
      }
    if (s.arrays.empty())
      throw InputError(file, "", "no cell array named vf_<material>; name the fraction "
                                 "arrays explicitly");
  } else {
    for (const auto& n : requested_arrays(data, options.arrays, file)) {
      s.arrays.push_back(data.find_cell_array(n));
      names.push_back(n.size() > 3 && n.compare(0, 3, "vf_") == 0 ? n.substr(3) : n);
    }
  }
  for (const auto* a : s.arrays)
    if (a->n_components != 1)
      throw InputError(file, "", "fraction array '" + a->name + "' has " +
                                     std::to_string(a->n_components) +
                                     " components, expected 1");
  for (std::size_t k = 0; k < s.arrays.size(); ++k) s.material.push_back(static_cast<int>(k));
  if (options.void_material.empty()) return s;
  const auto named = std::find(names.begin(), names.end(), options.void_material);
  if (named == names.end()) {
    s.void_material = static_cast<int>(names.size());
    names.push_back(options.void_material);
    return s;
  }
  s.void_material = static_cast<int>(named - names.begin());
  s.arrays.erase(s.arrays.begin() + s.void_material);
  s.material.erase(s.material.begin() + s.void_material);
  return s;
}

std::string cell_where(CellId c) { return "cell " + std::to_string(c.value()); }

}  // namespace

Fractions extract_fractions(const io::MeshData& data, const FractionOptions& options,
                            FractionReport* report, const std::string& file) {
  if (!options.labels.empty()) {
    if (report) *report = FractionReport();
    return fractions_from_labels(data, options, file);
  }
  std::vector<std::string> names;
  const Selection selected = fraction_arrays(data, options, names, file);
  const auto& arrays = selected.arrays;
  Fractions f(data.n_cells(), names);
  FractionReport rep;
  const bool has_void = selected.void_material >= 0;
  const int n_read = static_cast<int>(arrays.size());
  for (CellId c : id_range<CellId>(data.n_cells())) {
    // Validate and clip, check the sum on the values as given, then drop traces and rescale.
    double sum = 0;
    for (int m = 0; m < n_read; ++m) {
      double v = arrays[static_cast<std::size_t>(m)]->values[c.idx()];
      if (std::isnan(v) || v < -options.value_tolerance || v > 1 + options.value_tolerance) {
        std::ostringstream msg;
        msg << "fraction " << arrays[static_cast<std::size_t>(m)]->name << " = " << v
            << " is outside [0, 1] (tolerance " << options.value_tolerance << ")";
        throw InputError(file, cell_where(c), msg.str());
      }
      if (v < 0 || v > 1) {
        v = std::clamp(v, 0.0, 1.0);
        ++rep.clipped_values;
      }
      f(c, selected.material[static_cast<std::size_t>(m)]) = v;
      sum += v;
    }
    if (has_void) {
      if (sum > 1 + options.sum_tolerance) {
        std::ostringstream msg;
        msg << "fractions sum to " << sum << ", above 1 (tolerance " << options.sum_tolerance
            << "): no room for the void material";
        throw InputError(file, cell_where(c), msg.str());
      }
      f(c, selected.void_material) = std::max(0.0, 1 - sum);
      sum += f(c, selected.void_material);
    }
    const double err = std::abs(sum - 1);
    rep.max_sum_error = std::max(rep.max_sum_error, err);
    if (err > options.sum_tolerance) {
      std::ostringstream msg;
      msg << "fractions sum to " << sum << " (tolerance " << options.sum_tolerance << "); "
          << (sum > 1 ? "a larger sum tolerance would rescale the cell"
                      : "name a void material to fill the remainder, or raise the sum tolerance");
      throw InputError(file, cell_where(c), msg.str());
    }
    double kept = 0;
    for (int m = 0; m < f.n_materials(); ++m) {
      if (f(c, m) > 0 && f(c, m) < options.zero_below) {
        f(c, m) = 0;
        ++rep.zeroed_values;
      }
      kept += f(c, m);
    }
    if (kept <= 0) throw InputError(file, cell_where(c), "every fraction is a trace or zero");
    if (std::abs(kept - 1) > 1e-12) {
      ++rep.rescaled_cells;
      for (int m = 0; m < f.n_materials(); ++m) f(c, m) /= kept;
    }
  }
  if (report) *report = rep;
  return f;
}

}  // namespace hexadapt
