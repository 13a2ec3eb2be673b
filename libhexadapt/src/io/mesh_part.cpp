// io::migrate: each rank packs, per destination, the cells going there (global ids, global
// node ids, arrays) and the nodes they use (global ids, points, point arrays); a receiver
// sorts what came by global id, keeping one copy of a node several ranks sent.
#include "hexadapt/io/mesh_part.h"

#include <algorithm>
#include <numeric>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/routing.h"
#include "mesh_rows.h"

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

std::vector<Parcel> parcels(const MeshPart& part, const std::vector<int>& to, int n) {
  const MeshData& d = part.data;
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  const auto cw = static_cast<std::size_t>(detail::row_width(false, d.cell_data));
  const auto nw = static_cast<std::size_t>(detail::row_width(true, d.point_data));
  const std::vector<double> cell_rows =
      detail::rows_of(nullptr, d.cell_data, static_cast<std::size_t>(d.n_cells()));
  const std::vector<double> node_rows = detail::rows_of(&d.points, d.point_data, d.points.size());
  std::vector<Parcel> out(static_cast<std::size_t>(n));
  std::vector<int> sent_to(d.points.size(), -1);  // the last destination a node was packed for
  for (int r = 0; r < n; ++r) {
    Parcel& p = out[static_cast<std::size_t>(r)];
    for (std::size_t c = 0; c < to.size(); ++c) {
      if (to[c] != r) continue;
      p.cell_ids.push_back(part.cell_ids[c]);
      p.cell_rows.insert(p.cell_rows.end(), cell_rows.begin() + static_cast<std::ptrdiff_t>(c * cw),
                         cell_rows.begin() + static_cast<std::ptrdiff_t>((c + 1) * cw));
      for (std::size_t v = 0; v < npc; ++v) {
        const std::size_t node = d.cells[c * npc + v].idx();
        p.cell_nodes.push_back(part.node_ids[node]);
        if (sent_to[node] == r) continue;
        sent_to[node] = r;
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
    }
  std::vector<Parcel> in(static_cast<std::size_t>(n));
  in[static_cast<std::size_t>(comm.rank())] = std::move(out[static_cast<std::size_t>(comm.rank())]);
  if (n == 1) return in;
  std::vector<dist::Buffer> got = dist::exchange(comm, peers, send);
  for (std::size_t i = 0; i < peers.size(); ++i)
    in[static_cast<std::size_t>(peers[i])] = unpacked(got[i]);
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

}  // namespace

MeshPart migrate(const dist::Communicator& comm, const MeshPart& part, const std::vector<int>& to) {
  const MeshData& d = part.data;
  if (to.size() != static_cast<std::size_t>(d.n_cells()))
    throw InternalError("a destination for " + std::to_string(to.size()) + " of " +
                        std::to_string(d.n_cells()) + " cells");
  for (const int r : to)
    if (r < 0 || r >= comm.size()) throw InternalError("destination rank " + std::to_string(r));
  const Parcel all = joined(delivered(comm, parcels(part, to, comm.size())));
  MeshPart out;
  out.n_cells = part.n_cells;
  out.n_nodes = part.n_nodes;
  MeshData& m = out.data;
  m.dim = d.dim;
  m.metadata = d.metadata;
  m.cell_data = d.cell_data;
  m.point_data = d.point_data;
  // Nodes: one copy of each id, increasing.
  std::vector<std::size_t> order = order_of(all.node_ids);
  order.erase(
      std::unique(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return all.node_ids[a] == all.node_ids[b]; }),
      order.end());
  for (const std::size_t i : order) out.node_ids.push_back(all.node_ids[i]);
  detail::set_rows(rows_in(all.node_rows,
                           static_cast<std::size_t>(detail::row_width(true, m.point_data)), order),
                   order.size(), &m.points, m.point_data);
  // Cells: increasing id, their nodes found among the nodes.
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  order = order_of(all.cell_ids);
  for (const std::size_t c : order) {
    out.cell_ids.push_back(all.cell_ids[c]);
    for (std::size_t v = 0; v < npc; ++v) {
      const auto it =
          std::lower_bound(out.node_ids.begin(), out.node_ids.end(), all.cell_nodes[c * npc + v]);
      m.cells.push_back(NodeId(static_cast<index_t>(it - out.node_ids.begin())));
    }
  }
  detail::set_rows(rows_in(all.cell_rows,
                           static_cast<std::size_t>(detail::row_width(false, m.cell_data)), order),
                   order.size(), nullptr, m.cell_data);
  return out;
}

}  // namespace hexadapt::io
