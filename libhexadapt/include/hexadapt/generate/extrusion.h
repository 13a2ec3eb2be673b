// Extrusion: a quad mesh swept along z into k layers of hexes, the paper's "3D extruded"
// cases (sec. 6: the 2D inputs run again as 420x180x3 grids).
//
// Hex (layer l, quad q) has id l * n_quads + q and node (layer l, node n) has id
// l * n_nodes + n, so per-cell data of the quad mesh repeats layer after layer.
#pragma once

#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt::generate {

/// `layers` layers of thickness `thickness` from z = z0. Throws OptionError when layers < 1
/// or thickness <= 0.
HexMesh extrude(const QuadMesh& mesh, int layers, double thickness, double z0 = 0);

}  // namespace hexadapt::generate
