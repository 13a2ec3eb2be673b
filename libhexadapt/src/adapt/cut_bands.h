// Where the parts adapted on the ranks of an MPI job meet: the second pass of the iterative
// interface displacement. Each rank adapted its part with the nodes it shares with other
// ranks (the cuts) frozen, and their copies where the cells around them were pillowed, so the
// parts fit together but the cuts' interface nodes stayed on the staircase. Then, for every
// group of ranks holding some node together (two ranks beside a cut; three or more where cuts
// meet), the ranks of the group each send the others the cells of their part within a few
// rings of the group's nodes, build the same band mesh from the halves (in rank order), and
// move its nodes on with the guaranteed method's last steps (resume_moves): the cut's nodes
// are now inside the band, its outer nodes and the nodes a rank outside the group holds
// frozen. Every rank of the group computes the same moves from the same band, so each takes
// its own nodes' new positions and the parts still fit. The groups go in rounds in which no
// rank is in two groups (a slab's even cuts, then its odd ones). No cell is added: the layers
// across a cut are those the first pass laid, or none when its cells were left unpillowed.
#pragma once

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/dist/communicator.h"
#include "shared_nodes.h"

namespace hexadapt {

/// Moves the nodes within `rings` cells of every cut on, on every rank holding them; the
/// result's figures of the moved nodes follow (target, distances, near, blocked, sliding) and
/// those of the cells are recounted. The shared nodes are at the same points on every rank
/// holding them (share_nodes). Every rank calls it.
template <class M>
void resume_across_cuts(const dist::Communicator& comm, AdaptResult<M>& r,
                        const SharedNodes& shared, int rings, const AdaptOptions& options);

}  // namespace hexadapt
