// Extrusion: a quad mesh swept along z into k layers of hexes, the paper's "3D extruded"
// cases (sec. 6: the 2D inputs run again as 420x180x3 grids).
//
// Hex (layer l, quad q) has id l * n_quads + q and node (layer l, node n) has id
// l * n_nodes + n, so per-cell data of the quad mesh repeats layer after layer.
#pragma once

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::generate {

/// The points and hexes of `quads` (dim 2) swept into `layers` layers of thickness
/// `thickness` from z = z0 (no arrays). Throws OptionError when layers < 1, thickness <= 0
/// or the data is not 2D.
io::MeshData extrude(const io::MeshData& quads, int layers, double thickness, double z0 = 0);

}  // namespace hexadapt::generate
