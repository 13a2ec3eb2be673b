// What colour each cell gets: a categorical palette for material indices (with the
// materials' names for the legend) or a continuous colour map over a cell field (with its
// colour bar: scale, range, ticks, threshold).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/quality/scaled_jacobian.h"
#include "ticks.h"

namespace hexadapt::render {

using Rgb = std::array<double, 3>;  ///< components in [0, 1]

struct LegendEntry {
  std::string label;
  Rgb color;
};

/// The colour bar of a continuous map: the values its colours span, the cells' own range,
/// round ticks, and for quality the threshold.
struct ColorBar {
  std::string title;
  double scale_min = 0, scale_max = 0;  ///< the values of the bottom and top colours
  /// Quality: the scale is fixed, the same in every picture, rather than the cells' range.
  bool fixed_scale = false;
  bool has_values = false;            ///< some cell has a finite value
  double data_min = 0, data_max = 0;  ///< the range of the cells' finite values
  std::vector<Tick> ticks;            ///< inside the scale
  std::optional<double> threshold;    ///< marked on the bar (quality: S_q)
  /// Colours outside the map, shown under the bar when some cell has them: below a fixed
  /// scale (inverted cells), no finite value.
  std::vector<LegendEntry> special;
};

struct CellColors {
  std::vector<Rgb> cell;            ///< one per cell of the mesh
  std::vector<LegendEntry> legend;  ///< categorical: one entry per material
  std::optional<ColorBar> bar;      ///< continuous: the colour bar
};

struct ColoringOptions {
  double threshold = default_threshold;  ///< S_q, marked on the bar of "quality"
  int max_ticks = 6;                     ///< ticks of the colour bar, at most
};

/// The k-th colour of the categorical palette (cycles after 10).
Rgb palette_color(int k);
/// The continuous colour map at t in [0, 1] (clamped): dark blue through green to yellow.
Rgb colormap(double t);

/// Material names from the file's data (io::material_names) or, failing that, from the
/// vf_<name> cell arrays in file order.
std::vector<std::string> legend_names(const io::MeshData& data);

/// Colours by `field`: "material" (categorical), "fractions" (each cell mixes the material
/// colours by its vf_ fractions), "quality" (scaled Jacobian computed here, on the fixed scale
/// from min(0, threshold) to 1 so that pictures of different meshes compare; cells below it
/// get their own colour), "none" (white), any cell array (continuous over the cells' range;
/// the magnitude of vector arrays) or, failing one, any point array (each cell the mean of its
/// nodes' values). Cells without a finite value are grey. Throws OptionError naming the
/// available fields and arrays when `field` is none of them.
CellColors color_cells(const io::MeshData& data, const std::string& field,
                       const ColoringOptions& options = {});

}  // namespace hexadapt::render
