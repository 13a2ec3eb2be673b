// The nodes a rank's part of a mesh needs from the other ranks for a search by position:
// every rank offers some of its owned nodes and names a box (its region of interest); each
// offered node goes to every other rank whose box holds it. Used by the mesh check on parts
// (duplicates, hanging nodes), where a node of one rank can lie near a node or face of
// another without sharing a cell with it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/mesh/part_ids.h"

namespace hexadapt {

/// Candidate nodes by position: indices into the part's points, the rank's own first, then
/// the other ranks' nodes, appended to the points.
class NearNodes {
 public:
  std::vector<NodeId> candidates;  ///< the offered nodes, then the received ones
  std::size_t n_offered = 0;       ///< candidates [0, n_offered) are the offered nodes
  std::size_t n_local = 0;         ///< points [0, n_local) are the part's own
  std::vector<std::int64_t> received_ids;
  std::vector<int> received_owner;

  /// The global id and the owning rank of point p.
  std::int64_t id(const PartIds& ids, std::size_t p) const {
    return p < n_local ? ids.node(p) : received_ids[p - n_local];
  }
  int owner(int rank, std::size_t p) const {
    return p < n_local ? rank : received_owner[p - n_local];
  }
};

/// This rank's offered nodes (indices into `points`, moved in), then the other ranks' offered
/// nodes inside `box`, in rank order, appended to `points` (the caller shrinks it back to
/// n_local when done). An empty box (lo > hi) receives nothing. Every rank calls it.
NearNodes nodes_near(const dist::Communicator& comm, const std::array<Vec3, 2>& box,
                     std::vector<Vec3>& points, std::vector<NodeId> offered, const PartIds& ids);

/// The bounding box of every rank's finite points, (0, 0) when there are none: the same
/// bits as bounding_box (point_grid.h) of all of them. Every rank calls it.
std::array<Vec3, 2> global_bounding_box(const dist::Communicator& comm,
                                        const std::vector<Vec3>& points);

/// The local index of global node id g in a part (owned nodes and local nodes come in
/// increasing global id); -1 when the part does not hold it.
std::int64_t local_node(const PartIds& ids, std::size_t n_nodes, std::int64_t g);

}  // namespace hexadapt
