// How a rank's part of a mesh spread over ranks sits in the whole mesh, as the checks and
// reports that run on parts see it: the global ids of its cells and nodes, which cells are
// its own (the first ones; the rest are a ghost layer) and which nodes it owns. Each cell and
// node of the whole mesh is owned by exactly one rank, so a figure summed over what every
// rank owns counts it once. The default is the whole mesh on one rank: every id its own.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/core/ids.h"

namespace hexadapt {

class PartIds {
 public:
  /// The whole mesh: local ids are global ids, everything owned.
  PartIds() = default;
  /// A part whose first `owned_cells` cells are its own; the vectors are referred to, not
  /// copied. Owned cells and owned nodes come in increasing global id.
  PartIds(const std::vector<std::int64_t>& cell_ids, index_t owned_cells,
          const std::vector<std::int64_t>& node_ids, const std::vector<char>& owns_node)
      : cells_(&cell_ids), nodes_(&node_ids), owns_node_(&owns_node), owned_cells_(owned_cells) {}

  bool is_whole() const { return cells_ == nullptr; }
  /// The global id of local cell c (node n).
  std::int64_t cell(std::size_t c) const {
    return cells_ ? (*cells_)[c] : static_cast<std::int64_t>(c);
  }
  std::int64_t node(std::size_t n) const {
    return nodes_ ? (*nodes_)[n] : static_cast<std::int64_t>(n);
  }
  /// The cells [0, owned_cells(n_cells)) are this rank's own.
  index_t owned_cells(index_t n_cells) const { return cells_ ? owned_cells_ : n_cells; }
  bool owns_node(std::size_t n) const { return !owns_node_ || (*owns_node_)[n] != 0; }

 private:
  const std::vector<std::int64_t>* cells_ = nullptr;
  const std::vector<std::int64_t>* nodes_ = nullptr;
  const std::vector<char>* owns_node_ = nullptr;
  index_t owned_cells_ = 0;
};

}  // namespace hexadapt
