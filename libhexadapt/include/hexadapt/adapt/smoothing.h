// Quality-preserving smoothing (paper sec. 5.1: "it must not decrease the quality and nodes
// that have reached the geometrical interfaces are fixed").
//
// Each movable node is pulled toward the mean of its edge neighbours, the displacement
// restricted by its constraint (boundary plane or edge, interface plane or curve: the node
// slides along them), and shortened by halves until the smallest score of the cells around
// the node (the scaled Jacobian, below it where a cell breaks the size criterion:
// quality/cell_score.h) does not go down; a move that cannot keep it is not made. A node whose
// cells stay poor then tries a pattern search along the axes (within its constraint) that
// only accepts a higher local minimum: it untangles what the Laplacian pull cannot. Nodes sharing
// no cell are moved in parallel in a fixed order, so the result does not depend on the thread
// count.
#pragma once

#include <limits>
#include <vector>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/core/ids.h"

namespace hexadapt {

struct SmoothOptions {
  int iterations = 20;  ///< sweeps over all movable nodes
  int halvings = 4;     ///< how many times a refused displacement is halved and retried
  /// A sweep that improves no node's local minimum by more than this stops the smoothing.
  double min_gain = 1e-6;
  /// Nodes whose local minimum stays below this also try the pattern search.
  double optimise_below = 0.5;
  int search_levels = 4;  ///< pattern-search step halvings (first step: 1/4 edge length)
  /// Laplacian pulls shorter than this many mean edge lengths around the node are not made.
  double min_move = 1e-2;
  /// A cell scoring at least this never drops below it (the threshold). The local minimum
  /// alone would let a node beside a cell below the threshold sink its other cells to that
  /// cell's score.
  double floor = -std::numeric_limits<double>::infinity();
};

struct SmoothResult {
  int iterations = 0;  ///< sweeps done
  index_t moves = 0;   ///< node moves made over all sweeps
  /// Nodes that a further sweep would try again: those that moved, or whose cells' nodes
  /// moved, after they were last tried. Every other movable node would stay where it is.
  std::vector<NodeId> unsettled;
};

/// Smooths the nodes with movable[n] != 0, keeping each within constraint[n]. A node is tried
/// again only after a node of its cells moved, which gives the result of full sweeps at the
/// cost of the region still changing. `start`, when given, lists the nodes to try first (the
/// other movable nodes are taken as settled: a previous call's `unsettled` plus the nodes
/// around what moved since gives the result of a call on every node). `size`: the size
/// criterion the scores include (off by default: the scores are the scaled Jacobians).
/// `neighbours`, when given, keeps the nodes' edge neighbours for further calls on meshes of
/// the same cells (a call without one computes them for itself).
template <class M>
SmoothResult smooth(M& mesh, const IdVector<NodeId, char>& movable,
                    const IdVector<NodeId, NodeConstraint>& constraint,
                    const SmoothOptions& options = {},
                    const std::vector<NodeId>* start = nullptr, const SizeCriterion& size = {},
                    NeighbourCache* neighbours = nullptr);

}  // namespace hexadapt
