// Where the slabs adapted on the ranks of an MPI job meet: the second pass of the iterative
// interface displacement. Each rank adapted its slab with the node layers it shares with the
// ranks beside it (the cuts) frozen, and their copies where the cells around them were
// pillowed, so the slabs fit together but the cuts' interface nodes stayed on the staircase.
// Then, for every cut, the two ranks beside it each send the other
// the cells of their mesh within a few rings of the cut, build the same band mesh from both
// halves (the lower rank's first), and move its nodes on with the guaranteed method's last
// steps (resume_moves): the cut's nodes are now inside the band, its outer nodes frozen.
// Both ranks compute the same moves from the same band, so each takes its own nodes' new
// positions and the meshes still fit. The even cuts go first, then the odd ones, so that no
// rank is in two bands at once. No cell is added: the layers across a cut are those the first
// pass laid, or none when its cells were left unpillowed.
#pragma once

#include <array>
#include <vector>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt::cli {

/// Which cut a node of a rank's part lies on: the cut's frozen nodes and their copies.
enum class CutSide : char { none = 0, below = 1, above = 2 };

/// One rank's slab as the bands see it.
template <class M>
struct SlabMesh {
  AdaptResult<M>& result;  ///< the rank's part of the mesh: nodes moved, node figures updated
  /// Per node of the part: the cut it lies on. A cut's nodes lie where the input's do and
  /// their copies where both ranks beside it placed them (pillow_frozen): the same points on
  /// both ranks, by which they are matched.
  const IdVector<NodeId, CutSide>& cut;
  /// The part's faces on its cut below and on its cut above (toward the other ranks' cells).
  const std::array<std::vector<typename M::FaceNodes>, 2>& cut_faces;
  bool below = false, above = false;  ///< a cut at the bottom, at the top
};

/// True on every rank when, at every cut, the faces of the two ranks' parts there are the same
/// (the same corners, to the bit): the parts fit together. Every rank calls it.
template <class M>
bool cuts_fit(const dist::Communicator& comm, const SlabMesh<M>& slab);

/// Moves the nodes within `rings` cells of every cut on, on the two ranks beside it; the
/// result's figures of the moved nodes follow (target, distances, near, blocked, sliding).
/// Every rank calls it.
template <class M>
void resume_across_cuts(const dist::Communicator& comm, const SlabMesh<M>& slab, int rings,
                        const AdaptOptions& options);

}  // namespace hexadapt::cli
