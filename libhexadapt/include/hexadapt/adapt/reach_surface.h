// Steps at the end of the guaranteed method: nodes the move-smooth loop left off their
// interface surface are put on it, and the cells around them are repaired by moving their
// neighbours.
//
// The loop moves one node at a time, every cell around it keeping the criteria; a node
// whose every step would sink a cell below the threshold stays where it is, although moving
// its neighbours as well would let it reach. Here a node off its surface (farther than
// near_interface local sizes) is put on it (the foot of its distance), and the nodes around
// it then optimise their cells (smoothing.h, the pattern search only): the nodes without a
// target within two cells of it, and the nodes with a target sharing a cell with it, which
// slide on their own surfaces. The move is kept when every cell around these nodes meets
// the criteria (the threshold and the size criterion); otherwise the node tries 3/4 of the
// way, then just enough to come within near_interface, and stays where it was when none
// holds (a node that comes closer without reaching stays there and tries again on the next
// pass). Nodes whose regions share no cell are repaired together, in a fixed order, and the
// passes repeat while a node reaches its surface, so the result is the same whatever the
// thread count.
//
// Measured on the 3D cases of docs/results.md: the blocked nodes sit beside cells at
// 0.300-0.31 (vortex filaments one cell thick, balldrop's air two cells thick under the
// drop), which one node moving alone cannot raise.
//
// reach_targets does the same, at the very end of a run, for the nodes short of their
// targets (most of them on their surface: the controlled move slid them there, to the
// nearest ring around the target where every cell kept the criteria): such a node goes onto
// its target, then 3/4 of the way, and only the nodes without a target sharing a cell with
// it repair its cells, so that no other node leaves its own target. On the triple point
// 420x180x3 at t = 1, the size criterion left four nodes 0.06 local sizes short of their
// targets: an edge to a node without a target would have been 0.95 times the shortest
// allowed; that node moved aside, they reach them. On the fully 3D cases it lowers the
// target distance ratio by a quarter to a half (docs/results.md).
#pragma once

#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/core/ids.h"

namespace hexadapt {

struct ReachOptions {
  int passes = 3;  ///< passes over the nodes still off their surface; 0 = none
};

/// Of reach_surfaces, or of reach_targets, where "off" means off the node's target.
struct ReachResult {
  index_t off_surface = 0;  ///< nodes off their surface before the first pass
  index_t still_off = 0;    ///< nodes off their surface after the last pass
  index_t moves = 0;        ///< moves kept, onto a surface or toward it, over all passes
  /// Passes made: they stop when one brings no node closer, or at ReachOptions::passes.
  int passes = 0;
};

/// Puts the nodes farther than near_interface local sizes from their surface (`surface`:
/// sliding_constraints()) on it where the cells around them can be repaired to meet
/// `threshold` and the size criterion; `smooth`: the smoothing settings the repair starts
/// from. Throws OptionError for passes < 0.
template <class M>
ReachResult reach_surfaces(M& mesh, const Targets& targets,
                           const IdVector<NodeId, NodeConstraint>& surface,
                           const SizeCriterion& size, const ReachOptions& options,
                           const SmoothOptions& smooth, double threshold, double near_interface);

/// Puts the nodes with a target anywhere but on it onto it, or 3/4 of the way, where the
/// nodes without a target around them can repair their cells to meet `threshold` and the
/// size criterion; the other nodes with a target stay. Throws OptionError for passes < 0.
template <class M>
ReachResult reach_targets(M& mesh, const Targets& targets,
                          const IdVector<NodeId, NodeConstraint>& surface,
                          const SizeCriterion& size, const ReachOptions& options,
                          const SmoothOptions& smooth, double threshold);

}  // namespace hexadapt
