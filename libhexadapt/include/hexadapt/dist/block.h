// The part of a mesh one rank holds, and which of it the rank owns.
//
// A Block is either a range or a list. A range is a contiguous range of the global mesh's
// cells, in the global order, and the contiguous range of its nodes, so local id + offset is
// the global id: what a structured grid cut into slabs across its last axis gives (cell
// (i, j, k) is i + nx (j + ny k)), and the whole mesh is the one-rank case. A list names the
// global id of every cell and node held: what a partitioner's part of an unstructured mesh
// with its ghost layers gives (io::GhostedPart). The rank owns a sub-range of the held cells
// (a list's first ones) and some of the nodes: the cells and nodes it decides for; the others
// are ghosts, held to see around the owned ones and owned by another rank.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {

struct Block {
  std::int64_t cell_offset = 0;  ///< a range's global id of local cell 0
  std::int64_t node_offset = 0;  ///< a range's global id of local node 0
  index_t held_cells = 0, held_nodes = 0;
  index_t owned_cell_first = 0, owned_cell_end = 0;  ///< local ids of the owned cells
  index_t owned_node_first = 0, owned_node_end = 0;  ///< a range's local ids of the owned nodes
  /// A list's global id of each held cell (the owned ones, then the ghosts, each group
  /// increasing) and node (increasing), and per node whether the rank owns it; empty in a range.
  std::vector<std::int64_t> cell_ids, node_ids;
  std::vector<char> owns_node;

  /// The whole mesh, owned by its one rank.
  static Block whole(index_t n_cells, index_t n_nodes);
  /// A list (above): the first `owned_cells` of `cell_ids` are the rank's own.
  static Block listed(std::vector<std::int64_t> cell_ids, index_t owned_cells,
                      std::vector<std::int64_t> node_ids, std::vector<char> owns_node);

  bool is_list() const { return !cell_ids.empty() || !node_ids.empty(); }
  std::int64_t global(CellId c) const {
    return is_list() ? cell_ids[c.idx()] : cell_offset + c.value();
  }
  std::int64_t global(NodeId n) const {
    return is_list() ? node_ids[n.idx()] : node_offset + n.value();
  }
  /// The local id of global cell g, or an invalid id when this block does not hold it.
  CellId local_cell(std::int64_t g) const;
  /// The local id of global node g, or an invalid id when this block does not hold it.
  NodeId local_node(std::int64_t g) const;
  bool owns(CellId c) const { return c.value() >= owned_cell_first && c.value() < owned_cell_end; }
  bool owns(NodeId n) const {
    return is_list() ? owns_node[n.idx()] != 0
                     : n.value() >= owned_node_first && n.value() < owned_node_end;
  }
};

/// The id in the whole mesh of local cell c of `block`, or c's own without a block.
inline std::int64_t global_cell(const Block* block, CellId c) {
  return block ? block->global(c) : c.value();
}

/// Where a stage runs: the ranks, and the block of the mesh this rank holds.
struct Distribution {
  const Communicator& comm;
  Block block;
  /// The whole mesh on one rank.
  template <class M>
  static Distribution whole(const M& mesh) {
    return {serial(), Block::whole(mesh.n_cells(), mesh.n_nodes())};
  }
};

/// A rank's slab of a structured grid of `cells` per axis (the unused axis 1 in 2D), cut
/// across its last axis (z in 3D, y in 2D) into one slab of contiguous layers per rank.
struct Slab {
  Block block;
  std::array<int, 3> held{};          ///< cells per axis of the part held (owned and ghost layers)
  int first_layer = 0;                ///< global index of the first layer held, along the cut axis
  std::array<int, 2> owned_layers{};  ///< global indices [first, end) of the layers owned
};

/// Rank `rank`'s slab of `size`, holding `ghost_layers` layers of cells beyond its own on each
/// side (fewer at the grid's ends). It owns its layers of cells and the node layers below
/// them; the last rank also owns the last node layer. Throws OptionError when a rank would
/// own no layer (more ranks than layers) or the grid is empty.
Slab structured_slab(const std::array<int, 3>& cells, int dim, int rank, int size,
                     int ghost_layers);

/// The same, cut by `layer_weights` (one finite weight >= 0 per layer across the last axis,
/// e.g. the bytes a stage needs for the layer) instead of layer counts: the heaviest rank's
/// sum of weights is as small as a cut into contiguous layers allows, every rank owning at
/// least one layer; the earlier ranks take what they can. Throws OptionError as
/// structured_slab does and on a negative or non-finite weight.
Slab weighted_slab(const std::array<int, 3>& cells, int dim, int rank, int size, int ghost_layers,
                   const std::vector<double>& layer_weights);

/// Every layer's sum of `owned` (one value per cell this rank owns in `slab`, in cell order)
/// over the whole grid, on every rank. A layer is summed in cell order by the rank owning
/// it, so the sums do not depend on the number of ranks or the cut.
std::vector<double> layer_sums(const Communicator& comm, const Slab& slab,
                               const std::vector<double>& owned);

}  // namespace hexadapt::dist
