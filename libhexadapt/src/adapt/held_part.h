// A rank's part of the grid adapt runs on across the ranks (adapt_on_ranks.h): the cells it
// holds, which of them are its own, the rank owning each, the nodes the ranks share (frozen)
// and the targets of its nodes as one process computes them on the whole grid.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "hexadapt/adapt/adapt_on_ranks.h"

namespace hexadapt {

struct HeldPart {
  AssignedGrid grid;                      ///< the cells held
  index_t first_cell = 0, own_cells = 0;  ///< the own cells among them: [first, first + own)
  /// The input nodes a part lists first, in order (a slab's own node layers; none of a mesh).
  std::array<index_t, 2> first_nodes{};
  /// What the volume offset's sums count here: the own cells, and the nodes this rank decides
  /// for (each node of the whole input counted by one rank).
  IdVector<CellId, char> counted_cells;
  IdVector<NodeId, char> counted_nodes;
  /// The cuts' nodes: those of the own cells that other ranks' own cells use too, frozen so
  /// that the parts fit together there.
  IdVector<NodeId, char> frozen;
  std::vector<int> cell_owner;  ///< the rank owning each cell held
  /// Of the nodes held; those of the own cells as one process computes them on the whole grid.
  Targets targets;
};

/// Replaces each value with its sum over the ranks, added in rank order. Every rank calls it.
std::function<void(std::vector<double>&)> summed_over_ranks(const dist::Communicator& comm);

/// The part of the cells `grid` this rank holds, `where.block` naming them, and of a slab
/// `slab`; its targets computed with `options`' (in the whole grid's frame, the volume offset's
/// sums over what every rank counts). Every rank calls it.
HeldPart held_part(AssignedGrid&& grid, const dist::Distribution& where,
                   const std::optional<SlabPlace>& slab, const AdaptOptions& options);

}  // namespace hexadapt
