#include "hexadapt/dist/block.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "hexadapt/core/error.h"

namespace hexadapt::dist {

Block Block::whole(index_t n_cells, index_t n_nodes) {
  Block b;
  b.held_cells = b.owned_cell_end = n_cells;
  b.held_nodes = b.owned_node_end = n_nodes;
  return b;
}

Block Block::listed(std::vector<std::int64_t> cell_ids, index_t owned_cells,
                    std::vector<std::int64_t> node_ids, std::vector<char> owns_node) {
  if (owns_node.size() != node_ids.size() || owned_cells < 0 ||
      static_cast<std::size_t>(owned_cells) > cell_ids.size())
    throw InternalError("a list block of " + std::to_string(cell_ids.size()) + " cells (" +
                        std::to_string(owned_cells) + " owned) and " +
                        std::to_string(node_ids.size()) + " nodes (" +
                        std::to_string(owns_node.size()) + " owner flags)");
  Block b;
  b.held_cells = static_cast<index_t>(cell_ids.size());
  b.held_nodes = static_cast<index_t>(node_ids.size());
  b.owned_cell_end = owned_cells;
  b.cell_ids = std::move(cell_ids);
  b.node_ids = std::move(node_ids);
  b.owns_node = std::move(owns_node);
  return b;
}

namespace {

// The place of g in the increasing ids [first, end), or -1.
index_t place_in(const std::vector<std::int64_t>& ids, index_t first, index_t end, std::int64_t g) {
  const auto b = ids.begin() + first, e = ids.begin() + end;
  const auto it = std::lower_bound(b, e, g);
  return it != e && *it == g ? static_cast<index_t>(it - ids.begin()) : -1;
}

}  // namespace

CellId Block::local_cell(std::int64_t g) const {
  if (is_list()) {
    index_t l = place_in(cell_ids, 0, owned_cell_end, g);
    if (l < 0) l = place_in(cell_ids, owned_cell_end, held_cells, g);
    return l >= 0 ? CellId(l) : CellId();
  }
  const std::int64_t l = g - cell_offset;
  return l >= 0 && l < held_cells ? CellId(static_cast<index_t>(l)) : CellId();
}

NodeId Block::local_node(std::int64_t g) const {
  if (is_list()) {
    const index_t l = place_in(node_ids, 0, held_nodes, g);
    return l >= 0 ? NodeId(l) : NodeId();
  }
  const std::int64_t l = g - node_offset;
  return l >= 0 && l < held_nodes ? NodeId(static_cast<index_t>(l)) : NodeId();
}

namespace {

void check_cut(const std::array<int, 3>& cells, int dim, int size) {
  for (std::size_t a = 0; a < static_cast<std::size_t>(dim); ++a)
    if (cells[a] < 1) throw OptionError("an empty grid cannot be cut into slabs");
  const int layers = cells[static_cast<std::size_t>(dim - 1)];
  if (size < 1 || size > layers)
    throw OptionError(std::to_string(size) + " ranks cannot each own a layer of a grid with " +
                      std::to_string(layers) + " layers of cells across its last axis");
}

// The slab owning layers [own_first, own_end) of the last axis; `last` says whether it is
// the last rank's (which also owns the last node layer).
Slab slab_of(const std::array<int, 3>& cells, int dim, int own_first, int own_end, bool last,
             int ghost_layers) {
  const auto axis = static_cast<std::size_t>(dim - 1);
  const int layers = cells[axis];
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
  s.owned_layers = {own_first, own_end};
  Block& b = s.block;
  b.cell_offset = cells_per_layer * first;
  b.node_offset = nodes_per_layer * first;
  b.held_cells = static_cast<index_t>(cells_per_layer * (end - first));
  b.held_nodes = static_cast<index_t>(nodes_per_layer * (end - first + 1));
  b.owned_cell_first = static_cast<index_t>(cells_per_layer * (own_first - first));
  b.owned_cell_end = static_cast<index_t>(cells_per_layer * (own_end - first));
  const int own_node_end = last ? own_end + 1 : own_end;
  b.owned_node_first = static_cast<index_t>(nodes_per_layer * (own_first - first));
  b.owned_node_end = static_cast<index_t>(nodes_per_layer * (own_node_end - first));
  return s;
}

// The cut at bottleneck `cap`: each rank in turn owns the layers that keep its sum within
// `cap`, at least one, and leaves at least one layer to each rank after it. Returns the
// first layer of every rank and the layer count.
std::vector<int> greedy_cut(const std::vector<double>& w, int size, double cap) {
  const int layers = static_cast<int>(w.size());
  std::vector<int> split{0};
  std::size_t l = 0;
  for (int r = 0; r + 1 < size; ++r) {
    double sum = w[l++];
    const auto last = static_cast<std::size_t>(layers - (size - 1 - r));
    while (l < last && sum + w[l] <= cap) sum += w[l++];
    split.push_back(static_cast<int>(l));
  }
  split.push_back(layers);
  return split;
}

// The cut whose heaviest rank is lightest (the linear partition problem): the greedy cut at
// the smallest feasible bottleneck, found by bisection. All weights zero: equal weights.
std::vector<int> weighted_splits(std::vector<double> w, int size) {
  double total = 0;
  for (std::size_t l = 0; l < w.size(); ++l) {
    if (!std::isfinite(w[l]) || w[l] < 0)
      throw OptionError("layer " + std::to_string(l) + " has the weight " + std::to_string(w[l]) +
                        ": weights must be finite and >= 0");
    total += w[l];
  }
  if (total == 0) {
    std::fill(w.begin(), w.end(), 1.0);
    total = static_cast<double>(w.size());
  }
  const auto heaviest = [&](const std::vector<int>& split) {
    double max = 0;
    for (std::size_t r = 0; r + 1 < split.size(); ++r) {
      double sum = 0;
      for (auto l = static_cast<std::size_t>(split[r]); l < static_cast<std::size_t>(split[r + 1]);
           ++l)
        sum += w[l];
      max = std::max(max, sum);
    }
    return max;
  };
  double lo = 0, hi = total;  // the cut at hi is feasible, at lo not (or lo = 0)
  for (int i = 0; i < 64 && lo < hi; ++i) {
    const double mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;
    (heaviest(greedy_cut(w, size, mid)) <= mid ? hi : lo) = mid;
  }
  return greedy_cut(w, size, hi);
}

}  // namespace

Slab structured_slab(const std::array<int, 3>& cells, int dim, int rank, int size,
                     int ghost_layers) {
  check_cut(cells, dim, size);
  const std::int64_t layers = cells[static_cast<std::size_t>(dim - 1)];
  const auto split = [&](int r) { return static_cast<int>(layers * r / size); };
  return slab_of(cells, dim, split(rank), split(rank + 1), rank + 1 == size, ghost_layers);
}

Slab weighted_slab(const std::array<int, 3>& cells, int dim, int rank, int size, int ghost_layers,
                   const std::vector<double>& layer_weights) {
  check_cut(cells, dim, size);
  const int layers = cells[static_cast<std::size_t>(dim - 1)];
  if (static_cast<int>(layer_weights.size()) != layers)
    throw InternalError(std::to_string(layer_weights.size()) + " layer weights for " +
                        std::to_string(layers) + " layers");
  const std::vector<int> split = weighted_splits(layer_weights, size);
  const auto r = static_cast<std::size_t>(rank);
  return slab_of(cells, dim, split[r], split[r + 1], rank + 1 == size, ghost_layers);
}

std::vector<double> layer_sums(const Communicator& comm, const Slab& slab,
                               const std::vector<double>& owned) {
  const Block& b = slab.block;
  const int n_owned = slab.owned_layers[1] - slab.owned_layers[0];
  const index_t cells = b.owned_cell_end - b.owned_cell_first;
  if (static_cast<index_t>(owned.size()) != cells)
    throw InternalError(std::to_string(owned.size()) + " values for " + std::to_string(cells) +
                        " owned cells");
  std::vector<double> sums(static_cast<std::size_t>(n_owned), 0.0);
  const index_t per_layer = n_owned > 0 ? cells / n_owned : 0;
  for (index_t c = 0; c < cells; ++c)
    sums[static_cast<std::size_t>(c / per_layer)] += owned[static_cast<std::size_t>(c)];
  return all_gather_values(comm, sums);
}

}  // namespace hexadapt::dist
