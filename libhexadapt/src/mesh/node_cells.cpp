#include "hexadapt/mesh/node_cells.h"

namespace hexadapt {

NodeCells::NodeCells(const std::vector<NodeId>& cells_nodes, int nodes_per_cell,
                     index_t n_nodes)
    : offsets_(static_cast<std::size_t>(n_nodes) + 1, 0) {
  for (NodeId n : cells_nodes) ++offsets_[n.idx() + 1];
  for (std::size_t i = 1; i < offsets_.size(); ++i) offsets_[i] += offsets_[i - 1];
  cells_.resize(cells_nodes.size());
  std::vector<std::int64_t> fill(offsets_.begin(), offsets_.end() - 1);
  const auto npc = static_cast<std::size_t>(nodes_per_cell);
  for (std::size_t k = 0; k < cells_nodes.size(); ++k)
    cells_[static_cast<std::size_t>(fill[cells_nodes[k].idx()]++)] = CellId(k / npc);
}

}  // namespace hexadapt
