#include "held_part.h"

#include <algorithm>
#include <functional>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/dist/routing.h"
#include "hexadapt/mesh/unit_frame.h"

namespace hexadapt {

namespace {

// A slab's own cells and node layers, what it counts and its cuts' nodes.
template <class M>
void place_in_slab(HeldPart& s, const M& mesh, const dist::Block& block, const SlabPlace& place) {
  const dist::Slab& slab = place.slab;
  const auto axis = static_cast<std::size_t>(M::dim - 1);
  const int first = slab.first_layer;
  const std::array<int, 2> owned{slab.owned_layers[0] - first, slab.owned_layers[1] - first};
  const bool below = slab.owned_layers[0] > 0;
  const bool above = slab.owned_layers[1] < place.grid_layers;
  const index_t n_cells = mesh.n_cells(), n_nodes = mesh.n_nodes();
  const int held = slab.held[axis];
  const index_t cells = n_cells / held, plane = n_nodes / (held + 1);
  s.first_cell = block.owned_cell_first;
  s.own_cells = block.owned_cell_end - s.first_cell;
  s.first_nodes = {owned[0] * plane, (owned[1] + 1) * plane};
  s.counted_cells.assign(static_cast<std::size_t>(n_cells), 0);
  for (index_t c = owned[0] * cells; c < owned[1] * cells; ++c) s.counted_cells[CellId(c)] = 1;
  // A cut's nodes are counted by the rank above it.
  s.counted_nodes.assign(static_cast<std::size_t>(n_nodes), 0);
  const int last = above ? owned[1] - 1 : owned[1];
  for (index_t v = owned[0] * plane; v < (last + 1) * plane; ++v) s.counted_nodes[NodeId(v)] = 1;
  s.frozen.assign(static_cast<std::size_t>(n_nodes), 0);
  for (index_t k = 0; k < plane; ++k) {
    if (below) s.frozen[NodeId(owned[0] * plane + k)] = 1;
    if (above) s.frozen[NodeId(owned[1] * plane + k)] = 1;
  }
}

// A part of an unstructured mesh cut by PT-Scotch: its own cells (the first ones) and the
// ghost layers around them.
template <class M>
void place_in_mesh(HeldPart& s, const M& mesh, const dist::Block& block) {
  s.own_cells = block.owned_cell_end;
  s.counted_cells.assign(static_cast<std::size_t>(mesh.n_cells()), 0);
  s.counted_nodes.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
  s.frozen.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
  IdVector<NodeId, char> in_own(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const bool own = block.owns(c);
    s.counted_cells[c] = own;
    for (NodeId v : mesh.cell_nodes(c))
      if (own)
        in_own[v] = 1;
      else
        s.frozen[v] = 1;  // a ghost's node; the cuts' are the own cells' among them
  }
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    s.frozen[v] = s.frozen[v] && in_own[v];
    s.counted_nodes[v] = block.owns(v);
  }
}

// The rank owning each cell held: of a slab, the last rank whose own layers start at the
// cell's layer or before; of a mesh, itself or, for a ghost, the rank listing it among its own
// cells. Every rank calls it.
template <class M>
std::vector<int> cell_owners(const dist::Distribution& where, const std::optional<SlabPlace>& slab) {
  const dist::Block& block = where.block;
  std::vector<int> owner;
  if (slab) {
    const std::vector<std::int64_t> starts = dist::all_gather_values(
        where.comm, std::vector<std::int64_t>{slab->slab.owned_layers[0]});
    const auto axis = static_cast<std::size_t>(M::dim - 1);
    const index_t per_layer = block.held_cells / slab->slab.held[axis];
    for (index_t c = 0; c < block.held_cells; ++c) {
      const std::int64_t layer = slab->slab.first_layer + c / per_layer;
      owner.push_back(
          static_cast<int>(std::upper_bound(starts.begin(), starts.end(), layer) - starts.begin()) -
          1);
    }
    return owner;
  }
  const auto first_ghost = static_cast<std::ptrdiff_t>(block.owned_cell_end);
  const std::vector<std::int64_t> own(block.cell_ids.begin(), block.cell_ids.begin() + first_ghost),
      ghosts(block.cell_ids.begin() + first_ghost, block.cell_ids.end());
  owner.assign(own.size(), where.comm.rank());
  for (const std::vector<int>& o : dist::other_holders(where.comm, ghosts, own)) {
    if (o.size() != 1)
      throw InternalError("a ghost cell owned by " + std::to_string(o.size()) + " ranks");
    owner.push_back(o.front());
  }
  return owner;
}

// The targets of the nodes held, those of the own cells' nodes as one process computes them
// on the whole grid: on the cells held, in the whole grid's frame, the volume offset's sums
// over what every rank counts. Every rank calls it.
template <class M>
void part_targets(const dist::Communicator& comm, HeldPart& s, const M& grid,
                  const AdaptOptions& options) {
  const UnitFrame frame = unit_frame(grid, comm);
  const M m = to_local(grid, frame);
  VolumeParts parts;
  parts.counted_cells = s.counted_cells;
  parts.counted_nodes = s.counted_nodes;
  parts.add_up = summed_over_ranks(comm);
  s.targets = compute_targets(m, s.grid.fractions, s.grid.material,
                              boundary_constraints(m, options.boundary.without_frozen()),
                              options.targets, &parts);
  for (Vec3& p : s.targets.position.raw()) p = frame.to_world(p);
  for (InterfaceFace& f : s.targets.faces) f.point = frame.to_world(f.point);
}

}  // namespace

std::function<void(std::vector<double>&)> summed_over_ranks(const dist::Communicator& comm) {
  return [&comm](std::vector<double>& values) {
    const std::vector<double> all = dist::all_gather_values(comm, values);
    std::fill(values.begin(), values.end(), 0.0);
    for (std::size_t k = 0; k < all.size(); ++k) values[k % values.size()] += all[k];
  };
}

HeldPart held_part(AssignedGrid&& grid, const dist::Distribution& where,
                   const std::optional<SlabPlace>& slab, const AdaptOptions& options) {
  HeldPart s;
  s.grid = std::move(grid);
  std::visit(
      [&](const auto& mesh) {
        using M = std::decay_t<decltype(mesh)>;
        dist::on_every_rank(where.comm, [&] {
          if (slab)
            place_in_slab(s, mesh, where.block, *slab);
          else
            place_in_mesh(s, mesh, where.block);
        });
        s.cell_owner = cell_owners<M>(where, slab);
        dist::on_every_rank(where.comm, [&] { part_targets(where.comm, s, mesh, options); });
      },
      s.grid.mesh);
  return s;
}

}  // namespace hexadapt
