// What colour each cell gets: a categorical palette for material indices (with the
// materials' names for the legend) or a continuous colour map over a cell field (with its
// range for the colour bar).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::render {

using Rgb = std::array<double, 3>;  ///< components in [0, 1]

struct LegendEntry {
  std::string label;
  Rgb color;
};

struct CellColors {
  std::vector<Rgb> cell;              ///< one per cell of the mesh
  std::vector<LegendEntry> legend;    ///< categorical: one entry per material
  bool has_bar = false;               ///< continuous: draw a colour bar
  std::string bar_title;
  double bar_min = 0, bar_max = 0;
};

/// The k-th colour of the categorical palette (cycles after 10).
Rgb palette_color(int k);
/// The continuous colour map at t in [0, 1] (clamped): dark blue through green to yellow.
Rgb colormap(double t);

/// Material names from the metadata (`material_names`, `hexadapt_materials` or `materials`:
/// comma-separated) or, failing that, from the vf_<name> cell arrays in file order.
std::vector<std::string> material_names(const io::MeshData& data);

/// Colours by `field`: "material" (categorical), "fractions" (each cell mixes the material
/// colours by its vf_ fractions), "quality" (scaled Jacobian computed here, bar from
/// min(0, lowest) to 1), "none" (white), or any cell array (continuous; the magnitude of vector arrays). Throws
/// OptionError naming the available arrays when `field` is not there.
CellColors color_cells(const io::MeshData& data, const std::string& field);

}  // namespace hexadapt::render
