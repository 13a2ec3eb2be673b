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
#include "hexadapt/dist/communicator.h"
#include "hexadapt/mesh/part_ids.h"

namespace hexadapt {

/// Candidate nodes by position, with their global ids and the rank owning each.
struct NearNodes {
  std::vector<Vec3> points;
  std::vector<std::int64_t> ids;
  std::vector<int> owner;
};

/// This rank's offered nodes (local indices into `points`, kept first, in the given order),
/// then the other ranks' offered nodes inside `box`, in rank order. An empty box (lo > hi)
/// receives nothing. Every rank calls it.
NearNodes nodes_near(const dist::Communicator& comm, const std::array<Vec3, 2>& box,
                     const std::vector<Vec3>& points, const std::vector<std::size_t>& offered,
                     const PartIds& ids);

/// The bounding box of every rank's finite points, (0, 0) when there are none: the same
/// bits as bounding_box (point_grid.h) of all of them. Every rank calls it.
std::array<Vec3, 2> global_bounding_box(const dist::Communicator& comm,
                                        const std::vector<Vec3>& points);

/// The local index of global node id g in a part (owned nodes and local nodes come in
/// increasing global id); -1 when the part does not hold it.
std::int64_t local_node(const PartIds& ids, std::size_t n_nodes, std::int64_t g);

}  // namespace hexadapt
