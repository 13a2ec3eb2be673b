// Jitter: seeded random displacement of grid nodes, turning a Cartesian grid into an
// unstructured-looking one (DESIGN sec. 7: "optional jitter of grid nodes") while keeping
// every cell's scaled Jacobian at or above a floor, so the quality guarantee of the paper
// (sec. 5) still has a valid input.
//
// Each node gets a displacement of up to `amplitude` times its shortest incident edge per
// axis, drawn from a counter-based generator keyed by (seed, node id): the result does not
// depend on the thread count. Nodes on the bounding box keep the coordinates that put them
// there (corners stay, edge and face nodes slide along the boundary). Cells that fall below
// the floor have their nodes' displacements halved, round after round; after `max_halvings`
// rounds the nodes of any cell still below are put back, so the floor always holds when the
// unjittered mesh satisfies it.
#pragma once

#include <cstdint>

#include "hexadapt/core/ids.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::generate {

struct JitterOptions {
  double amplitude = 0.2;    ///< displacement per axis, times the node's shortest edge, in [0, 0.5)
  double min_quality = 0.5;  ///< every cell keeps scaled Jacobian >= this, in (0, 1]
  std::uint64_t seed = 1;    ///< random stream
  int max_halvings = 6;      ///< rounds of halving before a bad cell's nodes are reset
};

struct JitterResult {
  index_t moved_nodes = 0;   ///< nodes that end away from their start
  index_t damped_nodes = 0;  ///< nodes whose displacement was reduced for quality
  double min_quality = 1;    ///< smallest cell scaled Jacobian after jitter
};

/// Moves the points of `mesh` (quads or hexes) in place. Throws OptionError when the
/// amplitude or floor is out of range or the mesh is already below the floor.
JitterResult jitter_nodes(io::MeshData& mesh, const JitterOptions& options);

/// The smallest scaled Jacobian over the cells of `mesh` (1 when it has none).
double min_scaled_jacobian(const io::MeshData& mesh);

}  // namespace hexadapt::generate
