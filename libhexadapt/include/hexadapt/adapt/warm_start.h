// A run of the first layer's mending (guaranteed_pipeline.cpp) starts where the run before it
// ended. The two differ only around the input cells the later run leaves out of its layers:
// elsewhere their pillowed meshes hold the same nodes, under other ids. A node is named
// across runs by the input node it is (a copy of) and the input cells its cells come from;
// where a node and the nodes of its cells are all named once in both runs, it takes the
// point it had at the end of the run before, and the smoothing starts from the others only.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"

namespace hexadapt {

/// Where a run's nodes ended, each under a name that does not depend on its id (a 64-bit
/// hash: two nodes of one mesh with the same name are left cold).
struct NodePlaces {
  std::vector<std::uint64_t> name;
  std::vector<Vec3> point;
  bool empty() const { return name.empty(); }
};

/// The names and points of mesh's nodes; `node_origin`, `cell_origin`: the input node and cell
/// each node and cell comes from.
template <class M>
NodePlaces node_places(const M& mesh, const IdVector<NodeId, NodeId>& node_origin,
                       const IdVector<CellId, CellId>& cell_origin);

/// Moves each node of mesh that is warm (it and the nodes of its cells are named once in
/// both `now`, mesh's places, and `before`) to its point in `before`. Returns the nodes sharing
/// a cell with a cold node, sorted: those a smoothing of all nodes would try first.
template <class M>
std::vector<NodeId> warm_start(M& mesh, const NodePlaces& now, const NodePlaces& before);

}  // namespace hexadapt
