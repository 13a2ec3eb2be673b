// Node-to-target distances (paper sec. 6, Table 1: dist_init, dist_final; DESIGN sec. 4.4).
//
// The adapt stage stores, for each interface node, the position it aims at in a point
// array of 3 components (`target` by default); nodes with no target carry NaN. dist is the
// sum over the nodes with a target of |position - target| (the exact sum, rounded once), max
// the largest one.
#pragma once

#include <string>

#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt {
namespace io {
struct MeshData;
struct GhostedPart;
}  // namespace io

struct TargetDistances {
  bool has_targets = false;  ///< the array exists
  index_t nodes = 0;         ///< nodes with a (finite) target
  double sum = 0;            ///< dist
  double max = 0;
  NodeId max_node;  ///< the lowest id reaching max
};

/// Throws InputError when the array exists with a number of components other than 3.
TargetDistances target_distances(const io::MeshData& mesh, const std::string& array = "target");

/// The same of a mesh spread over ranks (io::with_ghost_layers' parts): the distances of the
/// whole mesh, ids global, the same on every rank. Every rank calls it.
TargetDistances target_distances(const dist::Communicator& comm, const io::GhostedPart& part,
                                 const std::string& array = "target");
/// As a JSON object (text), fields in docs/reports.md.
std::string target_distances_json(const TargetDistances& d);

}  // namespace hexadapt
