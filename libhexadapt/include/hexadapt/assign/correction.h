// Full-mesh non-manifold resolution, the paper's Algorithm 1 (sec. 3.2).
//
// Starting from an assignment (usually the majority one), every node where a material is
// not manifold gets its cells reassigned to the best stored manifold configuration of its
// ball (enumerate.h); the change may break neighbouring nodes, which are treated in turn,
// until no node is non-manifold. A node treated again takes its next unused stored
// configuration (configuration_store.h), so the process cannot cycle; when a node has used
// all of them the correction stops and reports that node.
//
// One refinement of the paper: by default a visit takes the cheapest unused configuration
// that leaves every currently manifold neighbour of the node (the other nodes of its cells)
// manifold, and only when none does, the cheapest unused one. Choosing blindly by cost makes
// neighbouring nodes undo each other: on noisy 3D fractions the paper's order used up 20
// configurations per node and failed where this one converges (see the tests).
//
// Parallel and deterministic: the non-manifold nodes are treated in rounds. Each round
// takes them in order of position (x, then y, then z; node id only for coincident points)
// and selects greedily those whose balls share no cell with a ball already selected; the
// selected nodes are solved in parallel (their balls are disjoint, so no solution can undo
// another), the others wait for the next round. Neither the thread count nor the order in
// which nodes and cells are stored changes the result.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/core/log.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

struct CorrectionOptions {
  int keep = 20;          ///< manifold configurations stored per node (K); >= 1
  int max_materials = 5;  ///< candidate materials per node: the most present in its ball; >= 1
  std::int64_t max_leaves = 20'000'000;  ///< per node: complete configurations examined at most
  /// Take the cheapest unused configuration that keeps the node's manifold neighbours
  /// manifold, when one exists; false: strictly the next cheapest (the paper's order).
  bool spare_neighbours = true;
  Progress progress;  ///< called between rounds; nullptr: silent
};

/// The node whose stored configurations ran out.
struct CorrectionFailure {
  NodeId node;
  Vec3 position = Vec3::Zero();
  std::vector<int> materials;  ///< its candidate materials
  int stored = 0;              ///< configurations it had (all used)
};

struct CorrectionResult {
  CellMaterials labels;  ///< the assignment reached (final when solved)
  bool solved = false;   ///< no non-manifold node remains
  std::optional<CorrectionFailure> failure;
  index_t non_manifold_initial = 0;    ///< nodes non-manifold in the initial assignment
  int rounds = 0;                      ///< rounds of independent nodes
  index_t node_solves = 0;             ///< configurations applied (a node may count twice)
  index_t nodes_treated = 0;           ///< distinct nodes treated
  int max_visits = 0;                  ///< most configurations used by one node
  index_t cells_changed = 0;           ///< cells whose material differs from the initial one
  double cost_initial = 0;             ///< eq. (4) over the mesh, initial assignment
  double cost_final = 0;               ///< eq. (4) over the mesh, reached assignment
  std::int64_t leaves = 0;             ///< configurations examined by all enumerations
  index_t truncated_enumerations = 0;  ///< nodes whose enumeration hit max_leaves
  PhaseTimes times;                    ///< scan, solve, rescan, totals
};

/// Corrects `initial` on `mesh`. Throws OptionError for keep or max_materials < 1, and
/// Error when the sizes of fractions or labels do not match the mesh.
template <class M>
CorrectionResult correct_assignment(const M& mesh, const Fractions& fractions,
                                    CellMaterials initial, const CorrectionOptions& options = {});

/// The same on one rank's block of a distributed mesh (dist/block.h), every rank calling it
/// with its own block, fractions and initial labels of the cells it holds. The block must
/// hold two layers of cells around its owned nodes (their balls and their neighbours'). Each
/// round gathers the pending nodes on every rank and selects them in the same global order,
/// so the labels of the owned cells, and the statistics, are those of one rank holding the
/// whole mesh; the failure names the global node id. The costs are summed per rank, then
/// in rank order.
template <class M>
CorrectionResult correct_assignment(const M& mesh, const Fractions& fractions,
                                    CellMaterials initial, const CorrectionOptions& options,
                                    const dist::Distribution& where);

}  // namespace hexadapt::assign
