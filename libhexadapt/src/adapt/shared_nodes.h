// Where the parts adapted on the ranks of an MPI job from the parts of an unstructured mesh
// meet. Each rank adapted its own cells and the ghost layers around them with the nodes its
// own cells share with other ranks' (the cuts) frozen, and their copies where the cells around
// them were pillowed (BoundaryOptions::pillow_frozen). A cut's node, or a copy of one, is held
// by the ranks owning the input cells around it, any number of them, which name it alike (its
// input node and those cells, by their global ids). These take each such node to one point on
// every rank holding it, check that the parts' faces meet, and name each node in the gathered
// mesh once.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt {

/// The nodes of a rank's part that other ranks' parts hold too.
struct SharedNodes {
  /// Per node of the part: the other ranks holding it, increasing; empty for the others.
  std::vector<std::vector<int>> ranks;
  /// Per node other ranks hold: its name on each of them (its input node, then the input cells
  /// of the cells around it, by their global ids, increasing).
  std::vector<std::vector<std::int64_t>> key;
  /// The ranks owning cells this rank holds as ghosts, increasing: the same pairs seen from
  /// both sides, and every rank `ranks` names among them.
  std::vector<int> peers;

  /// Whether this rank counts node v (when no higher rank holds it): each node by one rank.
  bool counts(NodeId v, int rank) const {
    const std::vector<int>& r = ranks[v.idx()];
    return r.empty() || r.back() < rank;
  }
  /// Every rank holding node v, this one (`rank`) included, increasing: its group.
  std::vector<int> holders(NodeId v, int rank) const {
    std::vector<int> h = ranks[v.idx()];
    h.insert(std::lower_bound(h.begin(), h.end(), rank), rank);
    return h;
  }
  /// The index of rank q in `peers`.
  std::size_t peer_slot(int q) const {
    return static_cast<std::size_t>(std::lower_bound(peers.begin(), peers.end(), q) -
                                    peers.begin());
  }
};

/// Takes every shared node of `r` to one point on every rank holding it. Each rank smoothed the
/// copies among the cells it read, whose ghost cells differ from rank to rank: where the
/// layers of several materials meet at a cut, their points differ a little (up to 1.8e-4 of
/// a grid of 1 on the asteroid at 48^3; up to a third of a cell where four parts of a mesh
/// meet). The nodes of each group of holders take the first of these that no cell of any rank
/// of the group then fails a criterion more than before with: their lowest holder's points,
/// their highest holder's, then each of them with the taking rank's own free nodes around the
/// cells that then fail smoothed (nodes no other rank holds). False on every rank when none
/// holds for some group, when some cell fails once every group took its choice, or when a
/// rank holds a shared node by a name the ranks it names do not: the parts do not meet.
/// Every rank calls it.
template <class M>
bool share_nodes(const dist::Communicator& comm, AdaptResult<M>& r, const SharedNodes& shared,
                 const AdaptOptions& options);

/// True on every rank when every rank's faces toward another's part (`faces`, with the rank
/// across each in `across`) are that rank's faces toward it, corner by corner to the bit, and
/// their corners shared with it. Every rank calls it.
template <class M>
bool parts_meet(const dist::Communicator& comm, const M& mesh, const SharedNodes& shared,
                const std::vector<typename M::FaceNodes>& faces, const std::vector<int>& across);

/// For write_disjoint_pieces' gathering (drop_next_piece_nodes): each node of this rank's part
/// that a higher rank counts, with its id past this rank's own points in the gathered mesh
/// (the pieces in rank order, each without the nodes it does not count). Every rank calls it.
std::vector<std::pair<index_t, index_t>> nodes_counted_above(const dist::Communicator& comm,
                                                             const SharedNodes& shared);

}  // namespace hexadapt
