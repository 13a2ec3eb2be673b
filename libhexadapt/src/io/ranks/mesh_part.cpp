// io::migrate: each rank packs, per destination, the cells going there (global ids, global
// node ids, arrays) and the nodes they use (global ids, points, point arrays); a receiver
// sorts what came by global id, keeping one copy of a node several ranks sent.
#include "hexadapt/io/mesh_part.h"

#include <algorithm>
#include <numeric>

#include "../mesh_rows.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt::io {

namespace {

// What travels to one rank.
struct Parcel {
  std::vector<std::int64_t> cell_ids, cell_nodes, node_ids;
  std::vector<double> cell_rows, node_rows;
};

dist::Buffer packed(const Parcel& p) {
  dist::Buffer b;
  b.put_vector(p.cell_ids);
  b.put_vector(p.cell_nodes);
  b.put_vector(p.cell_rows);
  b.put_vector(p.node_ids);
  b.put_vector(p.node_rows);
  return b;
}

Parcel unpacked(dist::Buffer& b) {
  Parcel p;
  p.cell_ids = b.get_vector<std::int64_t>();
  p.cell_nodes = b.get_vector<std::int64_t>();
  p.cell_rows = b.get_vector<double>();
  p.node_ids = b.get_vector<std::int64_t>();
  p.node_rows = b.get_vector<double>();
  return p;
}

// For each rank r, the cells cells_to[r] (local ids, increasing) and the nodes they use.
std::vector<Parcel> parcels(const MeshPart& part,
                            const std::vector<std::vector<std::size_t>>& cells_to) {
  const MeshData& d = part.data;
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  const auto cw = static_cast<std::size_t>(detail::row_width(false, d.cell_data));
  const auto nw = static_cast<std::size_t>(detail::row_width(true, d.point_data));
  const std::vector<double> cell_rows =
      detail::rows_of(nullptr, d.cell_data, static_cast<std::size_t>(d.n_cells()));
  const std::vector<double> node_rows = detail::rows_of(&d.points, d.point_data, d.points.size());
  std::vector<Parcel> out(cells_to.size());
  std::vector<std::size_t> packed_for(d.points.size(), cells_to.size());  // last rank packed for
  for (std::size_t r = 0; r < cells_to.size(); ++r) {
    Parcel& p = out[r];
    for (const std::size_t c : cells_to[r]) {
      p.cell_ids.push_back(part.cell_ids[c]);
      p.cell_rows.insert(p.cell_rows.end(), cell_rows.begin() + static_cast<std::ptrdiff_t>(c * cw),
                         cell_rows.begin() + static_cast<std::ptrdiff_t>((c + 1) * cw));
      for (std::size_t v = 0; v < npc; ++v) {
        const std::size_t node = d.cells[c * npc + v].idx();
        p.cell_nodes.push_back(part.node_ids[node]);
        if (packed_for[node] == r) continue;
        packed_for[node] = r;
        p.node_ids.push_back(part.node_ids[node]);
        p.node_rows.insert(p.node_rows.end(),
                           node_rows.begin() + static_cast<std::ptrdiff_t>(node * nw),
                           node_rows.begin() + static_cast<std::ptrdiff_t>((node + 1) * nw));
      }
    }
  }
  return out;
}

// Every rank's parcel to this one: rank r's from the exchange, this rank's own kept.
std::vector<Parcel> delivered(const dist::Communicator& comm, std::vector<Parcel> out) {
  const int n = comm.size();
  std::vector<int> peers;
  std::vector<dist::Buffer> send;
  for (int r = 0; r < n; ++r)
    if (r != comm.rank()) {
      peers.push_back(r);
      send.push_back(packed(out[static_cast<std::size_t>(r)]));
      out[static_cast<std::size_t>(r)] = Parcel();
    }
  std::vector<Parcel> in(static_cast<std::size_t>(n));
  in[static_cast<std::size_t>(comm.rank())] = std::move(out[static_cast<std::size_t>(comm.rank())]);
  if (n == 1) return in;
  std::vector<dist::Buffer> got = dist::exchange(comm, peers, std::move(send));
  for (std::size_t i = 0; i < peers.size(); ++i) {
    in[static_cast<std::size_t>(peers[i])] = unpacked(got[i]);
    got[i] = dist::Buffer();
  }
  return in;
}

// The received parcels, one after another.
Parcel joined(std::vector<Parcel> in) {
  Parcel all;
  for (Parcel& p : in) {
    all.cell_ids.insert(all.cell_ids.end(), p.cell_ids.begin(), p.cell_ids.end());
    all.cell_nodes.insert(all.cell_nodes.end(), p.cell_nodes.begin(), p.cell_nodes.end());
    all.cell_rows.insert(all.cell_rows.end(), p.cell_rows.begin(), p.cell_rows.end());
    all.node_ids.insert(all.node_ids.end(), p.node_ids.begin(), p.node_ids.end());
    all.node_rows.insert(all.node_rows.end(), p.node_rows.begin(), p.node_rows.end());
    p = Parcel();
  }
  return all;
}

// The order that sorts `ids` (stable: the first of equal ids first).
std::vector<std::size_t> order_of(const std::vector<std::int64_t>& ids) {
  std::vector<std::size_t> order(ids.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  return order;
}

std::vector<double> rows_in(const std::vector<double>& rows, std::size_t width,
                            const std::vector<std::size_t>& order) {
  std::vector<double> out;
  out.reserve(order.size() * width);
  for (const std::size_t i : order)
    out.insert(out.end(), rows.begin() + static_cast<std::ptrdiff_t>(i * width),
               rows.begin() + static_cast<std::ptrdiff_t>((i + 1) * width));
  return out;
}

// `arrays` without their values.
std::vector<DataArray> headers_of(const std::vector<DataArray>& arrays) {
  std::vector<DataArray> out;
  for (const DataArray& a : arrays) out.push_back({a.name, a.n_components, a.type, {}});
  return out;
}

// The part holding `all`'s cells in the order `cells` gives and their nodes (one copy of
// each, increasing id), with `like`'s kind, metadata and array names.
MeshPart assembled(const MeshPart& like, const Parcel& all, const std::vector<std::size_t>& cells) {
  const MeshData& d = like.data;
  MeshPart out;
  out.n_cells = like.n_cells;
  out.n_nodes = like.n_nodes;
  MeshData& m = out.data;
  m.dim = d.dim;
  m.metadata = d.metadata;
  m.cell_data = headers_of(d.cell_data);
  m.point_data = headers_of(d.point_data);
  std::vector<std::size_t> nodes = order_of(all.node_ids);
  nodes.erase(
      std::unique(nodes.begin(), nodes.end(),
                  [&](std::size_t a, std::size_t b) { return all.node_ids[a] == all.node_ids[b]; }),
      nodes.end());
  for (const std::size_t i : nodes) out.node_ids.push_back(all.node_ids[i]);
  detail::set_rows(rows_in(all.node_rows,
                           static_cast<std::size_t>(detail::row_width(true, m.point_data)), nodes),
                   nodes.size(), &m.points, m.point_data);
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  for (const std::size_t c : cells) {
    out.cell_ids.push_back(all.cell_ids[c]);
    for (std::size_t v = 0; v < npc; ++v) {
      const auto it =
          std::lower_bound(out.node_ids.begin(), out.node_ids.end(), all.cell_nodes[c * npc + v]);
      m.cells.push_back(NodeId(static_cast<index_t>(it - out.node_ids.begin())));
    }
  }
  detail::set_rows(rows_in(all.cell_rows,
                           static_cast<std::size_t>(detail::row_width(false, m.cell_data)), cells),
                   cells.size(), nullptr, m.cell_data);
  return out;
}

// The global ids of the nodes of `cells` (local ids of `part`), increasing, merged into `ids`.
void add_nodes_of(const MeshPart& part, const std::vector<std::size_t>& cells,
                  std::vector<std::int64_t>& ids) {
  const auto npc = static_cast<std::size_t>(part.data.nodes_per_cell());
  for (const std::size_t c : cells)
    for (std::size_t v = 0; v < npc; ++v)
      ids.push_back(part.node_ids[part.data.cells[c * npc + v].idx()]);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// For each rank, the cells of `owned` (local ids, increasing) it holds with `layers` layers of
// ghosts: this rank all of them, another those within `layers` rings of node neighbours of
// its own. A layer asks who holds each node of the cells held so far (the first: `sharers`,
// the other ranks using each owned node); only node ids travel between layers.
std::vector<std::vector<std::size_t>> cells_for_layers(const dist::Communicator& comm,
                                                       const MeshPart& owned, int layers,
                                                       std::vector<std::vector<int>> sharers) {
  const auto n = static_cast<std::size_t>(comm.size());
  const auto me = static_cast<std::size_t>(comm.rank());
  const MeshData& d = owned.data;
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  std::vector<std::vector<std::size_t>> cells_to(n);
  cells_to[me].resize(static_cast<std::size_t>(d.n_cells()));
  std::iota(cells_to[me].begin(), cells_to[me].end(), std::size_t{0});
  std::vector<std::int64_t> held = owned.node_ids;
  for (int layer = 0; layer < layers; ++layer) {
    const std::vector<std::vector<int>> wanters =
        layer == 0 ? std::move(sharers) : dist::other_holders(comm, owned.node_ids, held);
    std::vector<std::vector<std::size_t>> added(n);
    for (std::size_t c = 0; c < static_cast<std::size_t>(d.n_cells()); ++c)
      for (std::size_t v = 0; v < npc; ++v)
        for (const int s : wanters[d.cells[c * npc + v].idx()]) {
          const auto r = static_cast<std::size_t>(s);
          auto& list = added[r];
          if ((list.empty() || list.back() != c) &&
              !std::binary_search(cells_to[r].begin(), cells_to[r].end(), c))
            list.push_back(c);
        }
    std::vector<std::vector<std::int64_t>> nodes_to(n);
    for (std::size_t r = 0; r < n; ++r) {
      if (layer + 1 < layers) add_nodes_of(owned, added[r], nodes_to[r]);
      const auto middle = static_cast<std::ptrdiff_t>(cells_to[r].size());
      cells_to[r].insert(cells_to[r].end(), added[r].begin(), added[r].end());
      std::inplace_merge(cells_to[r].begin(), cells_to[r].begin() + middle, cells_to[r].end());
    }
    if (layer + 1 == layers) break;
    for (const auto& got : dist::all_to_all(comm, std::move(nodes_to)))
      held.insert(held.end(), got.begin(), got.end());
    std::sort(held.begin(), held.end());
    held.erase(std::unique(held.begin(), held.end()), held.end());
  }
  return cells_to;
}

}  // namespace

GhostedPart with_ghost_layers(const dist::Communicator& comm, const MeshPart& owned, int layers) {
  if (layers < 1) throw InternalError(std::to_string(layers) + " ghost layers");
  const std::vector<std::vector<int>> sharers =
      dist::other_holders(comm, owned.node_ids, owned.node_ids);
  const auto me = static_cast<std::size_t>(comm.rank());
  std::vector<Parcel> in =
      delivered(comm, parcels(owned, cells_for_layers(comm, owned, layers, sharers)));
  std::size_t first = 0;  // where this rank's own cells start once the parcels are joined
  for (std::size_t r = 0; r < me; ++r) first += in[r].cell_ids.size();
  const std::size_t n_owned = in[me].cell_ids.size();
  const Parcel all = joined(std::move(in));
  std::vector<std::size_t> cells(n_owned);
  std::iota(cells.begin(), cells.end(), first);
  std::vector<std::size_t> ghosts = order_of(all.cell_ids);
  ghosts.erase(std::remove_if(ghosts.begin(), ghosts.end(),
                              [&](std::size_t c) { return c >= first && c < first + n_owned; }),
               ghosts.end());
  cells.insert(cells.end(), ghosts.begin(), ghosts.end());
  GhostedPart out;
  out.part = assembled(owned, all, cells);
  out.owned_cells = static_cast<index_t>(n_owned);
  // This rank's own nodes that no lower rank uses; the ghosts' other nodes are not its own.
  out.owns_node.assign(out.part.node_ids.size(), 0);
  for (std::size_t v = 0; v < owned.node_ids.size(); ++v)
    if (sharers[v].empty() || sharers[v].front() > comm.rank())
      out.owns_node[static_cast<std::size_t>(
          std::lower_bound(out.part.node_ids.begin(), out.part.node_ids.end(), owned.node_ids[v]) -
          out.part.node_ids.begin())] = 1;
  return out;
}

MeshPart migrate(const dist::Communicator& comm, MeshPart part, const std::vector<int>& to) {
  if (to.size() != static_cast<std::size_t>(part.data.n_cells()))
    throw InternalError("a destination for " + std::to_string(to.size()) + " of " +
                        std::to_string(part.data.n_cells()) + " cells");
  std::vector<std::vector<std::size_t>> cells_to(static_cast<std::size_t>(comm.size()));
  for (std::size_t c = 0; c < to.size(); ++c) {
    if (to[c] < 0 || to[c] >= comm.size())
      throw InternalError("destination rank " + std::to_string(to[c]));
    cells_to[static_cast<std::size_t>(to[c])].push_back(c);
  }
  std::vector<Parcel> out = parcels(part, cells_to);
  MeshPart like;  // what assembled() takes of the part, which goes before anything travels
  like.n_cells = part.n_cells;
  like.n_nodes = part.n_nodes;
  like.data.dim = part.data.dim;
  like.data.metadata = std::move(part.data.metadata);
  like.data.cell_data = headers_of(part.data.cell_data);
  like.data.point_data = headers_of(part.data.point_data);
  part = MeshPart();
  const Parcel all = joined(delivered(comm, std::move(out)));
  return assembled(like, all, order_of(all.cell_ids));
}

}  // namespace hexadapt::io
