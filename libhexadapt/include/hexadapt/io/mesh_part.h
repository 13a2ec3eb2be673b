// A mesh spread over the ranks of a job, each rank holding some of its cells with global ids
// (io::merge_rank_pieces reads one from a .pvtu's pieces), and the move of cells between
// ranks (after a partitioner, dist/scotch_partition.h, chose where each goes).
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/dist/communicator.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/part_ids.h"

namespace hexadapt::io {

/// One rank's part of a mesh spread over the ranks: some of its cells, in increasing global
/// id, and the nodes they use, in increasing global id.
struct MeshPart {
  MeshData data;
  std::vector<std::int64_t> cell_ids;     ///< per cell of data: its id in the whole mesh
  std::vector<std::int64_t> node_ids;     ///< per point of data: its id in the whole mesh
  std::int64_t n_cells = 0, n_nodes = 0;  ///< of the whole mesh
};

/// Moves every rank's cells of `part` to the rank `to` names for each (with their arrays and
/// the nodes they use, points and point arrays): each rank then holds the cells sent to it
/// and their nodes, both in increasing global id, the same for any order of arrival. Every
/// rank calls it.
MeshPart migrate(const dist::Communicator& comm, MeshPart part, const std::vector<int>& to);

/// A rank's cells and layers of ghost cells around them.
struct GhostedPart {
  /// The owned cells first, then the ghosts, each group in increasing id.
  MeshPart part;
  /// How many of part's first cells this rank owns.
  index_t owned_cells = 0;
  /// Per node of part: this rank owns it (the lowest rank whose cells use it is this one).
  std::vector<char> owns_node;
};

/// How the part's cells and nodes sit in the whole mesh (refers to `g`, which must outlive it).
inline PartIds part_ids(const GhostedPart& g) {
  return PartIds(g.part.cell_ids, g.owned_cells, g.part.node_ids, g.owns_node);
}

/// Every rank's `owned` cells with `layers` layers (>= 1) of the other ranks' cells around
/// them: the first, the cells that share a node with an owned one (a node's whole star is
/// then on each rank using it); each next, the cells that share a node with one held so far.
/// Every rank calls it.
GhostedPart with_ghost_layers(const dist::Communicator& comm, const MeshPart& owned,
                              int layers = 1);

}  // namespace hexadapt::io
