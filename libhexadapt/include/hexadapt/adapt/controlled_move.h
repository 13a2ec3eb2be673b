// Quality-controlled node movement (paper sec. 5.1) and the uncontrolled direct move of the
// base algorithm (Fig. 10-a).
//
// Each node with a target moves toward it in `steps` equal steps (k / steps of the way from
// where it started); a step is taken only if every cell around the node keeps a scaled
// Jacobian >= threshold and its shortest edge >= the size criterion's floor (size_criterion.h;
// a cell already failing may not get worse). A node that
// is refused stays where it is and tries again on the next round, so a neighbour moving away
// can unblock it; rounds stop when no node advances. With `drag`, a refused step is tried
// once more with the node's free edge neighbours ahead of it (no target, not fixed by the
// domain boundary, on the side it moves to) moved by the same displacement, projected on
// their boundary constraint, then, if refused, with all its free edge neighbours moved; it
// is kept when every cell around the node and around them keeps the criteria. A free node
// in front of an interface node then makes way for it instead of stopping it at the size
// criterion (most of the nodes the criterion stopped in 2D), and a node of a pillowed
// interface carries its layer copies along instead of shearing the layer cells (in 3D, most
// of the nodes the move left off their surface). Drags run one node after another, after
// each parallel pass, in the set's order. When the interface surfaces are given
// (the plane, line or point through each target that the node may slide on: the interface
// normals and the domain boundary, sliding_constraints()), a node still short of its target
// then slides onto its surface instead: it takes the nearest ring of points of the surface
// around the target (1/16, 1/8, 1/4, 3/8, 1/2 of its cells' local size away, or of its mean
// edge length without local sizes) that holds a point keeping the criteria, the best point of that
// ring. A target that only a sliver or a flat cell could reach is thus replaced by another point of
// the same interface. Nodes that share no cell move in parallel (independent_node_sets), in a fixed
// order: the result is the same whatever the thread count.
#pragma once

#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/step_settings.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/core/ids.h"

namespace hexadapt {

struct MoveOptions {
  int steps = 16;      ///< a node moves 1/steps of its way at a time
  int max_rounds = 0;  ///< rounds over all nodes; 0 = 4 * steps
  bool drag = true;    ///< a refused step is retried with free neighbours dragged along
};

struct MoveResult {
  IdVector<NodeId, char> reached;  ///< 1: the node got to its target (or had none)
  /// 1: the node got to its target or slid onto its surface (or had no target).
  IdVector<NodeId, char> on_surface;
  index_t n_slid = 0;     ///< nodes that slid onto their surface away from their target
  index_t n_moving = 0;   ///< nodes that had somewhere to go
  index_t n_reached = 0;  ///< of those, how many got all the way
  index_t n_drags = 0;    ///< steps taken with free nodes dragged along
  int rounds = 0;
  double dist = 0;  ///< sum over target nodes of |position - target| after
};

/// Moves the nodes with targets.has set, keeping shared.threshold and the size criterion (off
/// by default); `surface`, when given, lets the nodes left short slide onto their target's
/// surface. Throws OptionError for steps < 1.
template <class M>
MoveResult controlled_move(M& mesh, const Targets& targets, const MoveOptions& options = {},
                           const StepSettings& shared = {}, const SizeCriterion& size = {},
                           const IdVector<NodeId, NodeConstraint>* surface = nullptr);

/// Puts every node with a target on it, whatever happens to the cells (base algorithm).
template <class M>
MoveResult direct_move(M& mesh, const Targets& targets);

}  // namespace hexadapt
