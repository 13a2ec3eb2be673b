// Node -> cells adjacency in compressed (CSR) form, shared by QuadMesh and HexMesh.
//
// Built on demand from the cell list, once, thread-safely; each node's cells are listed in
// increasing cell id, so every traversal built on it is deterministic.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/core/span.h"

namespace hexadapt {

class NodeCells {
 public:
  NodeCells() = default;
  /// cells_nodes: n_cells * nodes_per_cell node ids, cell after cell.
  NodeCells(const std::vector<NodeId>& cells_nodes, int nodes_per_cell, index_t n_nodes);
  Span<CellId> of(NodeId n) const {
    const auto b = static_cast<std::size_t>(offsets_[n.idx()]);
    const auto e = static_cast<std::size_t>(offsets_[n.idx() + 1]);
    return Span<CellId>(cells_.data() + b, e - b);
  }

 private:
  std::vector<std::int64_t> offsets_;
  std::vector<CellId> cells_;
};

/// Holds a NodeCells built the first time it is asked for. Copying a mesh does not copy
/// the cache (it is rebuilt on demand).
class LazyNodeCells {
 public:
  LazyNodeCells() : state_(std::make_unique<State>()) {}
  LazyNodeCells(const LazyNodeCells&) : LazyNodeCells() {}
  LazyNodeCells& operator=(const LazyNodeCells&) {
    state_ = std::make_unique<State>();
    return *this;
  }
  LazyNodeCells(LazyNodeCells&&) noexcept = default;
  LazyNodeCells& operator=(LazyNodeCells&&) noexcept = default;

  template <class Build>
  const NodeCells& get(Build&& build) const {
    std::call_once(state_->once, [&] { state_->csr = build(); });
    return state_->csr;
  }

 private:
  struct State {
    std::once_flag once;
    NodeCells csr;
  };
  std::unique_ptr<State> state_;
};

}  // namespace hexadapt
