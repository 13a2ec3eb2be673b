#include "coloring.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/core/error.h"
#include "hexadapt/io/material_names.h"
#include "hexadapt/measure/quality_report.h"

namespace hexadapt::render {
namespace {

Rgb hex_color(unsigned v) {
  return {static_cast<double>((v >> 16) & 0xffu) / 255.0,
          static_cast<double>((v >> 8) & 0xffu) / 255.0, static_cast<double>(v & 0xffu) / 255.0};
}

const Rgb below_scale{0.91, 0.16, 0.54};  // off the blue-green-yellow map: stands out
const Rgb no_value{0.6, 0.6, 0.6};

// The range of the finite values (NaN and infinities have no place on a scale).
void data_range(const std::vector<double>& values, ColorBar& bar) {
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    bar.data_min = bar.has_values ? std::min(bar.data_min, v) : v;
    bar.data_max = bar.has_values ? std::max(bar.data_max, v) : v;
    bar.has_values = true;
  }
}

Rgb mapped_color(double v, const ColorBar& bar, bool& below, bool& missing) {
  if (!std::isfinite(v)) {
    missing = true;
    return no_value;
  }
  if (bar.fixed_scale && v < bar.scale_min) {
    below = true;
    return below_scale;
  }
  const double span = bar.scale_max - bar.scale_min;
  return colormap(span > 0 ? (v - bar.scale_min) / span : 0.5);
}

// Colours the cells on the bar's scale, then finishes the bar: its ticks and the swatches
// of the colours outside the map that some cell has.
CellColors continuous(const std::vector<double>& values, ColorBar bar, int max_ticks) {
  CellColors c;
  bool below = false, missing = false;
  for (double v : values) c.cell.push_back(mapped_color(v, bar, below, missing));
  bar.ticks = nice_ticks(bar.scale_min, bar.scale_max, max_ticks);
  if (below)
    bar.special.push_back({"below " + range_label(bar.scale_min, bar.scale_min, bar.scale_max) +
                               (bar.scale_min == 0 ? " (inverted)" : ""),
                           below_scale});
  if (missing) bar.special.push_back({"no value (NaN, inf)", no_value});
  c.bar = std::move(bar);
  return c;
}

// The scaled Jacobian on a fixed scale: the same colour is the same quality in every
// picture, whatever the mesh's own range.
CellColors quality_colors(const io::MeshData& data, const ColoringOptions& options) {
  const std::vector<double> q = cell_qualities(data).scaled_jacobian;
  ColorBar bar;
  bar.title = "scaled Jacobian";
  bar.fixed_scale = true;
  bar.scale_min = std::min(0.0, options.threshold);
  bar.scale_max = 1.0;
  bar.threshold = options.threshold;
  data_range(q, bar);
  return continuous(q, std::move(bar), options.max_ticks);
}

// One value per tuple: the value itself, or the magnitude of a vector.
std::vector<double> tuple_values(const io::DataArray& a) {
  const auto nc = static_cast<std::size_t>(a.n_components);
  std::vector<double> values(a.n_tuples(), 0.0);
  for (std::size_t t = 0; t < values.size(); ++t) {
    double s = 0;
    for (std::size_t k = 0; k < nc; ++k) s += a.values[t * nc + k] * a.values[t * nc + k];
    values[t] = nc == 1 ? a.values[t] : std::sqrt(s);
  }
  return values;
}

// A point array seen on the cells: each cell takes the mean of its nodes' values (NaN
// when one of them has no finite value, so that the cell is shown as having none).
std::vector<double> cell_means(const io::MeshData& data, const std::vector<double>& node_value) {
  const auto per_cell = static_cast<std::size_t>(data.nodes_per_cell());
  std::vector<double> values(static_cast<std::size_t>(data.n_cells()), 0.0);
  for (std::size_t c = 0; c < values.size(); ++c) {
    for (std::size_t k = 0; k < per_cell; ++k)
      values[c] += node_value[static_cast<std::size_t>(data.cells[c * per_cell + k].value())];
    values[c] /= static_cast<double>(per_cell);
  }
  return values;
}

// Values over their own range; `title` names them on the colour bar.
CellColors field_colors(const std::vector<double>& values, std::string title,
                        const ColoringOptions& options) {
  ColorBar bar;
  bar.title = std::move(title);
  data_range(values, bar);
  bar.scale_min = bar.data_min;
  bar.scale_max = bar.data_max;
  return continuous(values, std::move(bar), options.max_ticks);
}

// Each cell mixes the materials' colours in proportion to its fractions.
CellColors blended(const io::MeshData& data) {
  CellColors c;
  const std::vector<std::string> names = legend_names(data);
  std::vector<const io::DataArray*> arrays;
  for (const auto& n : names)
    if (const io::DataArray* a = data.find_cell_array("vf_" + n)) {
      c.legend.push_back({n, palette_color(static_cast<int>(arrays.size()))});
      arrays.push_back(a);
    }
  if (arrays.empty()) throw OptionError("--color fractions: the file has no vf_<name> arrays");
  const auto n = static_cast<std::size_t>(data.n_cells());
  for (std::size_t i = 0; i < n; ++i) {
    Rgb mix{0, 0, 0};
    double total = 0;
    for (std::size_t m = 0; m < arrays.size(); ++m) {
      const double f = std::clamp(arrays[m]->values[i], 0.0, 1.0);
      const Rgb p = c.legend[m].color;
      for (int k = 0; k < 3; ++k)
        mix[static_cast<std::size_t>(k)] += f * p[static_cast<std::size_t>(k)];
      total += f;
    }
    for (double& x : mix) x = total > 0 ? x / total : 1.0;
    c.cell.push_back(mix);
  }
  return c;
}

CellColors categorical(const io::MeshData& data, const io::DataArray& material) {
  CellColors c;
  const std::vector<std::string> names = legend_names(data);
  int largest = static_cast<int>(names.size()) - 1;
  for (double v : material.values) largest = std::max(largest, static_cast<int>(v));
  const Rgb unassigned{0.6, 0.6, 0.6};
  bool any_unassigned = false;
  for (double v : material.values) {
    const bool valid = v >= 0 && v == std::floor(v);
    any_unassigned = any_unassigned || !valid;
    c.cell.push_back(valid ? palette_color(static_cast<int>(v)) : unassigned);
  }
  for (int m = 0; m <= largest; ++m) {
    const auto k = static_cast<std::size_t>(m);
    c.legend.push_back(
        {k < names.size() ? names[k] : "material " + std::to_string(m), palette_color(m)});
  }
  if (any_unassigned) c.legend.push_back({"none", unassigned});
  return c;
}

std::string available_fields(const io::MeshData& data) {
  std::string s = "fractions, quality, none; cell arrays:";
  for (const auto& a : data.cell_data) s += " '" + a.name + "'";
  s += "; point arrays:";
  for (const auto& a : data.point_data) s += " '" + a.name + "'";
  return s;
}

}  // namespace

Rgb palette_color(int k) {
  // Ten well-separated hues (the usual "category10" set).
  static const unsigned colors[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                    0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
  return hex_color(colors[static_cast<unsigned>(k) % 10u]);
}

Rgb colormap(double t) {
  // Piecewise-linear through five stops of a perceptually ordered blue-green-yellow map.
  static const unsigned stops[] = {0x440154, 0x3b528b, 0x21918c, 0x5ec962, 0xfde725};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  const Rgb a = hex_color(stops[i]), b = hex_color(stops[i + 1]);
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

std::vector<std::string> legend_names(const io::MeshData& data) {
  std::vector<std::string> names = io::material_names(data);
  if (!names.empty()) return names;
  for (const auto& a : data.cell_data)
    if (a.name.rfind("vf_", 0) == 0) names.push_back(a.name.substr(3));
  return names;
}

CellColors color_cells(const io::MeshData& data, const std::string& field,
                       const ColoringOptions& options) {
  const auto n = static_cast<std::size_t>(data.n_cells());
  if (field == "none") {
    CellColors c;
    c.cell.assign(n, Rgb{1, 1, 1});
    return c;
  }
  if (field == "fractions") return blended(data);
  if (field == "quality") return quality_colors(data, options);
  if (const io::DataArray* a = data.find_cell_array(field)) {
    if (field == "material" && a->n_components == 1) return categorical(data, *a);
    return field_colors(tuple_values(*a), field, options);
  }
  if (const io::DataArray* a = data.find_point_array(field))
    return field_colors(cell_means(data, tuple_values(*a)), field + " (node mean)", options);
  throw OptionError("--color: no array '" + field + "' (available: " + available_fields(data) +
                    ")");
}

}  // namespace hexadapt::render
