// Targets far enough apart for the size criterion (size_criterion.h): the target correction
// where the criterion needs one.
//
// Two interface nodes joined by a grid edge can have targets closer than the shortest edge
// a cell may have: where the interface passes almost through a grid node, or where two
// interface segments meet at a sharp angle, both nodes project onto nearly the same point
// (stir 100x50x3 at t = 1: targets 0.0019 apart against a shortest edge of 0.002). Then no
// mesh has both nodes on their targets, and the guarantee holds them short of them.
//
// For every such edge, in increasing node order, the two targets are pushed apart along the
// line through them, each keeping to its node's sliding constraint (its domain boundary and
// interface planes), so that a target stays on its node's interface surface: the surface
// distance of every position is unchanged. The push leaves them `margin` times the edge's
// shortest length apart (the largest min_length of the cells around the edge); a node fixed
// by its constraints (a 2D triple point, a corner) stays, its neighbour moves the whole way.
// Sweeps repeat until no edge is short or `sweeps` ran; a target never moves more than
// `max_shift` local sizes in all.
//
// Before that, the two targets of an edge are swapped where reaching them would turn the
// edge's cells inside out (`uncross`). A riser of the staircase lies across the interface:
// both its nodes project onto nearly the same point, in an order that is noise. Reaching the
// interface, the riser turns onto it and each of its cells onto its material's side; that
// turn must keep the cells' orientation (the edge x the cell's side, in the grid and on the
// targets): the targets are swapped when it would turn every cell of the edge inside out,
// not where the cells disagree. Only targets closer than half the edge are judged. Without
// the swap the guarantee holds both nodes short, one of them a quarter of a local size away
// (the triple point 420x180 at t = 2, damBreak4phase at t = 2).
#pragma once

#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/targets.h"

namespace hexadapt {

struct TargetSpacingOptions {
  double margin = 1.25;    ///< targets end this many times the shortest edge apart
  int sweeps = 8;          ///< over every edge, at most
  double max_shift = 0.5;  ///< farthest a target moves, in local sizes of its node
  bool uncross = true;     ///< swap the targets of an edge that would turn its cells inside out
};

struct TargetSpacingResult {
  index_t short_edges = 0;  ///< edges whose targets were closer than the criterion allows
  index_t moved = 0;        ///< targets moved
  index_t left_short = 0;   ///< edges still short at the end (their nodes cannot move apart)
  double max_shift = 0;     ///< farthest a target moved, in local sizes of its node
  int sweeps = 0;
  index_t swapped = 0;  ///< edges whose two targets were swapped (uncross)
};

/// Moves `targets.position` in place on `grid` (the mesh the targets belong to, with `size`
/// on its cells); `sliding` is sliding_constraints() of the grid. Nothing when size is off.
template <class M>
TargetSpacingResult space_targets(const M& grid, const CellMaterials& material,
                                  const SizeCriterion& size,
                                  const IdVector<NodeId, NodeConstraint>& sliding, Targets& targets,
                                  const TargetSpacingOptions& options = {});

}  // namespace hexadapt
