#include "hexadapt/io/fractions_reader.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io {

namespace {

// The array names `entries` stand for: an entry naming a cell array is that array, whatever
// it holds ("Volume Fraction for Body, Nose"); another one holding commas lists the names
// between them ("vf_a,vf_b"). Throws InputError naming the first missing array.
std::vector<std::string> requested_arrays(const MeshData& data,
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
      throw InputError(file, "",
                       "no cell array named '" + n +
                           "' (the cell arrays: " + (known.empty() ? "none" : known) + ")");
    }
  return out;
}

// The arrays read and the material each fills; the void material, when named, is the
// remainder: appended after them, or in the place of the array of its name, which is then
// recomputed instead of read.
struct Selection {
  std::vector<const DataArray*> arrays;
  std::vector<int> material;  ///< per array, its material index
  int void_material = -1;     ///< its material index, -1 when none
};

Selection fraction_arrays(const MeshData& data, const FractionOptions& options,
                          std::vector<std::string>& names, const std::string& file) {
  Selection s;
  if (options.arrays.empty()) {
    for (const auto& a : data.cell_data)
      if (a.name.size() > 3 && a.name.compare(0, 3, "vf_") == 0) {
        s.arrays.push_back(&a);
        names.push_back(a.name.substr(3));
      }
    if (s.arrays.empty())
      throw InputError(file, "",
                       "no cell array named vf_<material>; name the fraction "
                       "arrays explicitly");
  } else {
    for (const auto& n : requested_arrays(data, options.arrays, file)) {
      s.arrays.push_back(data.find_cell_array(n));
      names.push_back(n.size() > 3 && n.compare(0, 3, "vf_") == 0 ? n.substr(3) : n);
    }
  }
  for (const auto* a : s.arrays)
    if (a->n_components != 1)
      throw InputError(file, "",
                       "fraction array '" + a->name + "' has " + std::to_string(a->n_components) +
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

// A cell named by its id in the whole grid (`block`: the part of it the data holds, if any).
std::string cell_where(CellId c, const dist::Block* block) {
  return "cell " + std::to_string(dist::global_cell(block, c));
}

StoredPrecision stored_precision(const Selection& s) {
  for (const auto* a : s.arrays)
    if (a->type == io::ScalarType::float32) return StoredPrecision::float32;
  return StoredPrecision::float64;
}

// Reads cell c's values into f, validated and clipped into [0, 1]; returns their sum.
double read_cell(const Selection& s, CellId c, const dist::Block* block,
                 const FractionOptions& options, Fractions& f, FractionReport& rep,
                 const std::string& file) {
  double sum = 0;
  for (std::size_t m = 0; m < s.arrays.size(); ++m) {
    double v = s.arrays[m]->values[c.idx()];
    if (std::isnan(v) || v < -options.value_tolerance || v > 1 + options.value_tolerance) {
      std::ostringstream msg;
      msg << "fraction " << s.arrays[m]->name << " = " << v << " is outside [0, 1] (tolerance "
          << options.value_tolerance << ")";
      throw InputError(file, cell_where(c, block), msg.str());
    }
    if (v < 0 || v > 1) {
      v = std::clamp(v, 0.0, 1.0);
      ++rep.clipped_values;
    }
    f(c, s.material[m]) = v;
    sum += v;
  }
  return sum;
}

// How far cell c's sum (values clipped into [0, 1]) is from what the sum tolerance must
// accept: above 1 with a void material (it takes any remainder), away from 1 without.
double sum_error(const Selection& s, CellId c) {
  double sum = 0;
  for (const auto* a : s.arrays) sum += std::clamp(a->values[c.idx()], 0.0, 1.0);
  return s.void_material >= 0 ? sum - 1 : std::abs(sum - 1);
}

// The smallest number of two significant digits not below x: a tolerance that accepts x.
double accepting(double x) {
  const double step = std::pow(10.0, std::floor(std::log10(x)) - 1);
  double t = std::ceil(x / step) * step;
  while (t < x) t += step;
  return t;
}

// The error for cell c, whose sum is outside the tolerance: the sum, by how much, the
// tolerance and where it came from, and the --sum-tolerance that would accept this cell and
// every cell read (of the file, or with `block` of the cells a rank holds, named by their
// global ids). A sum below 1 can also take a void material; one above 1 cannot.
[[noreturn]] void throw_sum_error(const Selection& s, index_t n_cells, CellId c,
                                  const dist::Block* block, double sum, const FractionReport& rep,
                                  const std::string& file) {
  double largest = 0;
  for (CellId k : id_range<CellId>(n_cells)) largest = std::max(largest, sum_error(s, k));
  const double err = std::abs(sum - 1);
  std::ostringstream msg;
  msg << "fractions sum to " << std::setprecision(10) << sum << std::setprecision(3) << " (" << err
      << (sum > 1 ? " above" : " below") << " 1; sum tolerance " << rep.tolerances.sum_tolerance
      << (rep.tolerances.sum_tolerance_given
              ? ", given"
              : std::string(", the default for ") + precision_name(rep.precision) + " data")
      << "): ";
  if (sum < 1) msg << "name a void material ({void_material} NAME) to receive the remainder, or ";
  msg << "{sum_tolerance} " << accepting(err) << " would rescale this cell";
  if (largest > err) {
    msg << ", {sum_tolerance} " << accepting(largest) << " every cell";
    if (block && block->is_list())
      msg << " of the cells this rank holds";
    else if (block)
      msg << " of cells " << block->cell_offset << "-" << block->cell_offset + n_cells - 1
          << " (this rank's part)";
  }
  throw InputError(file, cell_where(c, block), msg.str());
}

// Sets the traces of cell c to 0 and rescales it to sum 1.
void clean_cell(CellId c, const dist::Block* block, Fractions& f, FractionReport& rep,
                const std::string& file) {
  double kept = 0;
  for (int m = 0; m < f.n_materials(); ++m) {
    if (f(c, m) > 0 && f(c, m) < rep.tolerances.zero_below) {
      f(c, m) = 0;
      ++rep.zeroed_values;
    }
    kept += f(c, m);
  }
  if (kept <= 0) throw InputError(file, cell_where(c, block), "every fraction is a trace or zero");
  if (std::abs(kept - 1) > 1e-12) {
    ++rep.rescaled_cells;
    for (int m = 0; m < f.n_materials(); ++m) f(c, m) /= kept;
  }
}

}  // namespace

Fractions extract_fractions(const MeshData& data, const FractionOptions& options,
                            FractionReport* report, const std::string& file,
                            const dist::Block* block) {
  FractionReport rep;
  if (block && !options.labels.empty() && options.label_values.empty())
    throw OptionError(
        "a label map gives one material per value found in the whole grid: a block needs the "
        "labels of every block (label_values)");
  if (!options.labels.empty()) {
    rep.tolerances =
        decide_tolerances(options.sum_tolerance, options.zero_below, StoredPrecision::float64, 1);
    if (report) *report = rep;
    return fractions_from_labels(data, options, file, block);
  }
  std::vector<std::string> names;
  const Selection selected = fraction_arrays(data, options, names, file);
  Fractions f(data.n_cells(), names);
  rep.precision = stored_precision(selected);
  rep.tolerances = decide_tolerances(options.sum_tolerance, options.zero_below, rep.precision,
                                     static_cast<int>(selected.arrays.size()));
  const double tolerance = rep.tolerances.sum_tolerance;
  FractionReport ghosts = rep;  // what the cells another rank owns would add
  for (CellId c : id_range<CellId>(data.n_cells())) {
    FractionReport& counted = block && !block->owns(c) ? ghosts : rep;
    // Validate and clip, check the sum on the values as given, then drop traces and rescale.
    double sum = read_cell(selected, c, block, options, f, counted, file);
    if (selected.void_material >= 0 && sum <= 1 + tolerance) {
      f(c, selected.void_material) = std::max(0.0, 1 - sum);
      sum += f(c, selected.void_material);
    }
    counted.max_sum_error = std::max(counted.max_sum_error, std::abs(sum - 1));
    if (std::abs(sum - 1) > tolerance)
      throw_sum_error(selected, data.n_cells(), c, block, sum, counted, file);
    clean_cell(c, block, f, counted, file);
  }
  if (report) *report = rep;
  return f;
}

}  // namespace hexadapt::io
