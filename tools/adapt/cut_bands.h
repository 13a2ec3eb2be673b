// Where the slabs adapted on the ranks of an MPI job meet: the second pass of the iterative
// interface displacement. Each rank adapted its slab with the node layers it shares with the
// ranks beside it (the cuts) frozen, so the slabs fit together but the cuts' interface nodes
// stayed on the staircase. Then, for every cut, the two ranks beside it each send the other
// the cells of their mesh within a few rings of the cut, build the same band mesh from both
// halves (the lower rank's first), and move its nodes on with the guaranteed method's last
// steps (resume_moves): the cut's nodes are now inside the band, its outer nodes frozen.
// Both ranks compute the same moves from the same band, so each takes its own nodes' new
// positions and the meshes still fit. The even cuts go first, then the odd ones, so that no
// rank is in two bands at once. No cell is added: the cells beside a cut, which the first
// pass could not pillow, keep their topology.
#pragma once

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt::cli {

/// One rank's slab as the bands see it.
template <class M>
struct SlabMesh {
  AdaptResult<M>& result;  ///< the rank's adapted mesh: nodes moved, node figures updated
  index_t plane = 0;       ///< nodes per cut: the first ones of the slab, and the last input ones
  index_t input_nodes = 0;
  bool below = false, above = false;  ///< a cut at the bottom, at the top
  /// The targets of the input nodes (has, position, interface) from the input cells on both
  /// sides of the cuts, as the run took them.
  Targets targets;
};

/// Moves the nodes within `rings` cells of every cut on, on the two ranks beside it; the
/// result's figures of the moved nodes follow (target, distances, near, blocked, sliding).
/// Every rank calls it.
template <class M>
void resume_across_cuts(const dist::Communicator& comm, SlabMesh<M>& slab, int rings,
                        const AdaptOptions& options);

}  // namespace hexadapt::cli
