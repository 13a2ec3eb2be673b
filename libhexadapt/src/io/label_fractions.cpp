// Label maps (segmented images, microstructures, what Sculpt reads as material ids): one
// integer per cell, turned into one material per distinct value with fraction 1 in its cells.
#include <cmath>
#include <set>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/fractions_reader.h"

namespace hexadapt::io {

namespace {

// Integers a double holds exactly, so labels survive a Float32/Float64 array.
constexpr double max_label = 9007199254740992.0;  // 2^53

std::int64_t label_of(const DataArray& a, std::size_t c, const std::string& file) {
  const double v = a.values[c];
  if (!(std::abs(v) <= max_label) || v != std::floor(v)) {
    std::ostringstream msg;
    msg << "label array " << quote_token(a.name) << " holds " << v
        << ", not an integer: a label map gives each cell an integer material id";
    throw InputError(file, "cell " + std::to_string(c), msg.str());
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

}  // namespace

Fractions fractions_from_labels(const MeshData& data, const FractionOptions& options,
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
  const auto n = static_cast<std::size_t>(data.n_cells());
  std::vector<std::int64_t> labels(n);
  std::set<std::int64_t> distinct;
  for (std::size_t c = 0; c < n; ++c) {
    labels[c] = label_of(*a, c, file);
    if (distinct.insert(labels[c]).second &&
        distinct.size() > static_cast<std::size_t>(options.max_labels))
      throw InputError(file, "cell " + std::to_string(c),
                       "label array " + quote_token(a->name) + " holds more than " +
                           std::to_string(options.max_labels) + " distinct labels");
  }
  std::vector<std::string> names;
  for (const std::int64_t l : distinct) {
    names.push_back(name_of(options, l));
    for (std::size_t k = 0; k + 1 < names.size(); ++k)
      if (names[k] == names.back())
        throw OptionError("two labels are named " + quote_token(names.back()));
  }
  Fractions f(data.n_cells(), names);
  for (std::size_t c = 0; c < n; ++c) {
    const auto m = std::distance(distinct.begin(), distinct.find(labels[c]));
    f(CellId(static_cast<index_t>(c)), static_cast<int>(m)) = 1.0;
  }
  return f;
}

}  // namespace hexadapt::io
