// The dual graph of a mesh spread over the ranks: cells are its vertices, and two cells are
// neighbours when they share a face (a hex's quad face, a quad's edge). What a partitioner
// takes to cut the mesh into parts of few shared faces.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {

/// A graph whose vertices are spread over the ranks in contiguous ranges, in rank order: this
/// rank's vertex v is global vertex first + v, its neighbours (global ids, increasing) are
/// neighbours[offsets[v] .. offsets[v + 1]).
struct DistGraph {
  std::int64_t first = 0;
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> neighbours;
  /// Per vertex, its weight (>= 1) for a partitioner to balance; empty: every vertex 1.
  std::vector<std::int64_t> weights;

  std::int64_t n_vertices() const { return static_cast<std::int64_t>(offsets.size()) - 1; }
};

/// The dual graph of the cells this rank holds (`nodes_per_cell` global node ids per cell, 4:
/// quads, 8: hexes in the kernel's binary order), every rank's cells numbered in rank order.
/// Faces are keyed by their sorted nodes: a face this rank holds twice pairs its two cells
/// here; the others go to the rank the key hashes to, which pairs the cells sharing it. (A
/// face of three cells or more, two of them here, misses the pairs with the others: a
/// partitioner's input, not a mesh check.) Every rank calls it.
DistGraph dual_graph(const Communicator& comm, int nodes_per_cell,
                     const std::vector<std::int64_t>& cell_nodes);

}  // namespace hexadapt::dist
