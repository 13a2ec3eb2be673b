// Label maps (segmented images, microstructures, what Sculpt reads as material ids): one
// integer per cell, turned into one material per distinct value with fraction 1 in its cells.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/fractions_reader.h"

namespace hexadapt::io {

namespace {

// Integers a double holds exactly, so labels survive a Float32/Float64 array.
constexpr double max_label = 9007199254740992.0;  // 2^53

std::int64_t label_of(const DataArray& a, std::size_t c, const dist::Block* block,
                      const std::string& file) {
  const double v = a.values[c];
  if (!(std::abs(v) <= max_label) || v != std::floor(v)) {
    std::ostringstream msg;
    msg << "label array " << quote_token(a.name) << " holds " << v
        << ", not an integer: a label map gives each cell an integer material id";
    throw InputError(
        file, "cell " + std::to_string(dist::global_cell(block, CellId(static_cast<index_t>(c)))),
        msg.str());
  }
  return static_cast<std::int64_t>(v);
}

void check_options(const FractionOptions& o) {
  if (!o.arrays.empty())
    throw OptionError("a label map (" + quote_token(o.labels) +
                      ") and fraction arrays cannot be given together");
  if (!o.void_material.empty())
    throw OptionError("a label map (" + quote_token(o.labels) +
                      ") has no void material: every cell has a label");
}

std::string name_of(const FractionOptions& o, std::int64_t label) {
  const auto it = o.label_names.find(label);
  return it != o.label_names.end() ? it->second : "label_" + std::to_string(label);
}

// The label array, checked.
const DataArray& label_array(const MeshData& data, const FractionOptions& options,
                             const std::string& file) {
  check_options(options);
  const DataArray* a = data.find_cell_array(options.labels);
  if (!a)
    throw InputError(file, "",
                     "no cell array named " + quote_token(options.labels) + " (the label map)");
  if (a->n_components != 1)
    throw InputError(file, "",
                     "label array " + quote_token(a->name) + " has " +
                         std::to_string(a->n_components) + " components, expected 1");
  return *a;
}

void check_label_count(const DataArray& a, std::size_t n, const FractionOptions& options,
                       const std::string& file, const std::string& where) {
  if (n > static_cast<std::size_t>(options.max_labels))
    throw InputError(file, where,
                     "label array " + quote_token(a.name) + " holds more than " +
                         std::to_string(options.max_labels) + " distinct labels");
}

}  // namespace

std::vector<std::int64_t> label_values(const MeshData& data, const FractionOptions& options,
                                       const std::string& file, const dist::Block* block) {
  const DataArray& a = label_array(data, options, file);
  std::set<std::int64_t> distinct;
  for (std::size_t c = 0; c < static_cast<std::size_t>(data.n_cells()); ++c)
    if (distinct.insert(label_of(a, c, block, file)).second)
      check_label_count(
          a, distinct.size(), options, file,
          "cell " + std::to_string(dist::global_cell(block, CellId(static_cast<index_t>(c)))));
  return {distinct.begin(), distinct.end()};
}

Fractions fractions_from_labels(const MeshData& data, const FractionOptions& options,
                                const std::string& file, const dist::Block* block) {
  const DataArray& a = label_array(data, options, file);
  const std::vector<std::int64_t> values = options.label_values.empty()
                                               ? label_values(data, options, file, block)
                                               : options.label_values;
  check_label_count(a, values.size(), options, file, "");
  std::vector<std::string> names;
  for (const std::int64_t l : values) {
    names.push_back(name_of(options, l));
    for (std::size_t k = 0; k + 1 < names.size(); ++k)
      if (names[k] == names.back())
        throw OptionError("two labels are named " + quote_token(names.back()));
  }
  Fractions f(data.n_cells(), names);
  for (std::size_t c = 0; c < static_cast<std::size_t>(data.n_cells()); ++c) {
    const auto it = std::lower_bound(values.begin(), values.end(), label_of(a, c, block, file));
    if (it == values.end() || *it != label_of(a, c, block, file))
      throw InternalError("a label of the block is not among the grid's labels");
    f(CellId(static_cast<index_t>(c)), static_cast<int>(it - values.begin())) = 1.0;
  }
  return f;
}

}  // namespace hexadapt::io
