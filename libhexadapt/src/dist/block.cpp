#include "hexadapt/dist/block.h"

#include <algorithm>
#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt::dist {

Block Block::whole(index_t n_cells, index_t n_nodes) {
  Block b;
  b.held_cells = b.owned_cell_end = n_cells;
  b.held_nodes = b.owned_node_end = n_nodes;
  return b;
}

CellId Block::local_cell(std::int64_t g) const {
  const std::int64_t l = g - cell_offset;
  return l >= 0 && l < held_cells ? CellId(static_cast<index_t>(l)) : CellId();
}

NodeId Block::local_node(std::int64_t g) const {
  const std::int64_t l = g - node_offset;
  return l >= 0 && l < held_nodes ? NodeId(static_cast<index_t>(l)) : NodeId();
}

Slab structured_slab(const std::array<int, 3>& cells, int dim, int rank, int size,
                     int ghost_layers) {
  const auto axis = static_cast<std::size_t>(dim - 1);
  const int layers = cells[axis];
  for (std::size_t a = 0; a < static_cast<std::size_t>(dim); ++a)
    if (cells[a] < 1) throw OptionError("an empty grid cannot be cut into slabs");
  if (size < 1 || size > layers)
    throw OptionError(std::to_string(size) + " ranks cannot each own a layer of a grid with " +
                      std::to_string(layers) + " layers of cells across its last axis");
  const auto split = [&](int r) {
    return static_cast<int>(static_cast<std::int64_t>(layers) * r / size);
  };
  const int own_first = split(rank), own_end = split(rank + 1);
  const int first = std::max(0, own_first - ghost_layers);
  const int end = std::min(layers, own_end + ghost_layers);

  std::int64_t cells_per_layer = 1, nodes_per_layer = 1;
  for (std::size_t a = 0; a < axis; ++a) {
    cells_per_layer *= cells[a];
    nodes_per_layer *= cells[a] + 1;
  }
  Slab s;
  s.held = cells;
  s.held[axis] = end - first;
  s.first_layer = first;
  Block& b = s.block;
  b.cell_offset = cells_per_layer * first;
  b.node_offset = nodes_per_layer * first;
  b.held_cells = static_cast<index_t>(cells_per_layer * (end - first));
  b.held_nodes = static_cast<index_t>(nodes_per_layer * (end - first + 1));
  b.owned_cell_first = static_cast<index_t>(cells_per_layer * (own_first - first));
  b.owned_cell_end = static_cast<index_t>(cells_per_layer * (own_end - first));
  const int own_node_end = rank + 1 == size ? own_end + 1 : own_end;
  b.owned_node_first = static_cast<index_t>(nodes_per_layer * (own_first - first));
  b.owned_node_end = static_cast<index_t>(nodes_per_layer * (own_node_end - first));
  return s;
}

}  // namespace hexadapt::dist
