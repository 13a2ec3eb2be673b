// A rank's part of the mesh it adapted: each rank of an MPI job adapts the layers it read,
// its own and the ghost layers beyond each cut, with the cuts' nodes frozen; the cells that
// come from its own layers are its part of the whole mesh. With the cells around the cuts
// pillowed (BoundaryOptions::pillow_frozen), both ranks beside a cut lay the same layers across
// it, so their parts meet there face to face.
#pragma once

#include <array>
#include <vector>

#include "hexadapt/adapt/adapt.h"

namespace hexadapt {

/// A rank's part, and its faces toward the cells of the ranks beside it (the cuts' faces).
template <class M>
struct OwnPart {
  AdaptResult<M> result;
  /// Per node of the part, when it is frozen (a cut's node or a copy of one): the input cells
  /// of the cells around it in the whole result, increasing, the other part's too; else none.
  std::vector<std::vector<CellId>> around;
  std::vector<typename M::FaceNodes> cut_faces;  ///< nodes of the part, each face's corners
  std::vector<CellId> cut_across;  ///< per cut face, the input cell of the cell across it
};

/// The part of `r` whose cells come from the input cells [cells[0], cells[1]), renumbered:
/// the input nodes [nodes[0], nodes[1]) first, in order, then every other node of those cells
/// in the order of `r`. Node origins are left in the ids of `r`'s grid; the figures of the
/// cells are not recounted (resume_across_cuts does).
template <class M>
OwnPart<M> own_part(AdaptResult<M> r, std::array<index_t, 2> cells, std::array<index_t, 2> nodes);

}  // namespace hexadapt
