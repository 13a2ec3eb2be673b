// Volume-conserving targets: each material's movable interface is offset along its normal
// so that the assigned grid, with its nodes on their targets, holds the material's input
// volume (the sum over cells of fraction x cell volume).
//
// A node's target is the mean of its faces' planes. That is exact for a planar interface, but
// it cuts the convex corners of a staircase and thins features a cell or two thick: on the
// stretched vortex (64^3, t = 1.5) the fluid ended 10.6 % short with every node on its
// target, against 6.5 % for the staircase itself.
//
// For every material a that is the smaller one (by input volume) of the two materials around
// some plain interface node (one interface direction, exactly two materials in its cells),
// those nodes are a's movers. Each sweep computes
//   error(a) = sum over a's cells of |c| at the targets - sum over all cells of f_a(c) |c|
//   rate(a)  = the rate at which a's cells gain volume when every mover of a moves along its
//              normal (oriented so that a grows): the area of a's movable interface
// (the rate measured once, on the first offsets) and moves every mover of a by
// -error(a) / rate(a), until every error is below volume_tolerance times the material's
// volume or volume_sweeps have run: one uniform offset per material, so the
// shape of the interface is kept (a node-by-node correction was tried and chased the
// staircase's checkerboard of errors). A mover's total offset stays within max_shift local
// sizes (the cube, in 2D square, root of the mean volume of its cells); boundary nodes move
// within their boundary constraint; nodes on triple curves keep their target. The offset
// makes every material's volume exact where the interface can absorb it, at the price of
// placing a resolved interface off its fractions' planes to make up for material the
// assignment lost elsewhere (thin filaments): the discrepancy can rise (docs/results.md).
//
// On a grid split among processes (VolumeParts), each holding its part with ghost layers
// around it, the volumes and rates are sums over the whole grid: each process counts its own
// cells and nodes, and the sums are added up across the processes at every sweep, so that
// every part offsets its targets as one process offsetting the whole grid would.
#pragma once

#include "hexadapt/adapt/targets.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

/// Offsets the targets in place (TargetOptions::volume_*); `parts`: when the mesh is one
/// process's part of a grid (nullptr: the whole grid).
template <class M>
void conserve_target_volumes(const M& mesh, const Fractions& fractions,
                             const CellMaterials& material,
                             const IdVector<NodeId, NodeConstraint>& boundary, Targets& targets,
                             const TargetOptions& options, const VolumeParts* parts = nullptr);

}  // namespace hexadapt
