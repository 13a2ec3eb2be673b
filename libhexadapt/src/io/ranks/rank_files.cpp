#include "hexadapt/io/rank_files.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "hexadapt/core/error.h"
#include "hexadapt/core/size_text.h"
#include "hexadapt/dist/dual_graph.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/io/mesh_part.h"
#include "hexadapt/io/vtk_collection.h"
#include "hexadapt/io/vtk_xml.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::io {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The cell layers of the held data this rank owns, relative to the held ones.
std::array<int, 2> owned_layers(const dist::Slab& slab, int dim) {
  const dist::Block& b = slab.block;
  const auto per_layer =
      static_cast<index_t>(b.held_cells / slab.held[static_cast<std::size_t>(dim - 1)]);
  return {b.owned_cell_first / per_layer, b.owned_cell_end / per_layer};
}

/// Rank 0's whole grid from every rank's owned piece (node layers shared by two pieces come
/// from the lower one), with rank 0's metadata and array names and types.
MeshData gathered(const dist::Communicator& comm, const MeshData& piece, const RankInput& input) {
  const int dim = input.shape.dim;
  const std::array<int, 3>& cells = input.shape.cells;
  std::size_t points_per_layer = 1;
  for (std::size_t a = 0; a + 1 < static_cast<std::size_t>(dim); ++a)
    points_per_layer *= static_cast<std::size_t>(cells[a]) + 1;
  const bool last = comm.rank() + 1 == comm.size();
  // This rank's node layers but the top one, which the rank above sends (the last rank sends
  // it too).
  const std::size_t n_points = last ? piece.points.size() : piece.points.size() - points_per_layer;
  dist::Buffer mine;
  std::vector<double> xyz;
  for (std::size_t i = 0; i < n_points; ++i)
    xyz.insert(xyz.end(), piece.points[i].data(), piece.points[i].data() + 3);
  mine.put_vector(xyz);
  for (const DataArray& a : piece.cell_data) mine.put_vector(a.values);
  for (const DataArray& a : piece.point_data)
    mine.put_vector(std::vector<double>(
        a.values.begin(),
        a.values.begin() +
            static_cast<std::ptrdiff_t>(n_points * static_cast<std::size_t>(a.n_components))));
  std::vector<dist::Buffer> all = dist::gather(comm, mine, 0);
  MeshData whole;
  if (comm.rank() != 0) return whole;
  whole.dim = dim;
  whole.metadata = piece.metadata;
  whole.structured_cells = cells;
  whole.cell_data = piece.cell_data;
  whole.point_data = piece.point_data;
  for (DataArray& a : whole.cell_data) a.values.clear();
  for (DataArray& a : whole.point_data) a.values.clear();
  for (dist::Buffer& b : all) {
    const std::vector<double> p = b.get_vector<double>();
    for (std::size_t i = 0; i + 2 < p.size(); i += 3)
      whole.points.emplace_back(p[i], p[i + 1], p[i + 2]);
    for (DataArray& a : whole.cell_data) {
      const std::vector<double> v = b.get_vector<double>();
      a.values.insert(a.values.end(), v.begin(), v.end());
    }
    for (DataArray& a : whole.point_data) {
      const std::vector<double> v = b.get_vector<double>();
      a.values.insert(a.values.end(), v.begin(), v.end());
    }
  }
  append_structured_cells(cells[0], cells[1], dim == 3 ? cells[2] : 0, whole.cells);
  return whole;
}

// The owned layers as .vts pieces placed in the whole grid, and the .pvts naming them.
void write_structured_pieces(const dist::Communicator& comm, const MeshData& owned,
                             const RankInput& input, const std::string& path,
                             const WriteOptions& options) {
  const auto axis = static_cast<std::size_t>(input.shape.dim - 1);
  std::array<int, 3> origin{0, 0, 0};
  origin[axis] = input.slab.first_layer + owned_layers(input.slab, input.shape.dim)[0];
  dist::Buffer mine;
  mine.put(origin[axis]);
  mine.put(owned.structured_cells[axis]);
  std::vector<StructuredPiece> pieces;
  int r = 0;
  for (dist::Buffer& b : dist::all_gather(comm, mine)) {
    StructuredPiece p{base_name(piece_path(path, r++)), {0, 0, 0}, input.shape.cells};
    p.origin[axis] = b.get<int>();
    p.cells[axis] = b.get<int>();
    pieces.push_back(p);
  }
  dist::on_every_rank(comm, [&] {
    write_vts(owned, piece_path(path, comm.rank()), options, origin);
    if (comm.rank() == 0) write_pvts(owned, input.shape.cells, pieces, path);
  });
}

// The bytes of a mesh's points, cells and arrays in memory.
double data_bytes(const MeshData& d) {
  double bytes =
      24.0 * static_cast<double>(d.points.size()) + 4.0 * static_cast<double>(d.cells.size());
  for (const auto* arrays : {&d.cell_data, &d.point_data})
    for (const DataArray& a : *arrays) bytes += 8.0 * static_cast<double>(a.values.size());
  return bytes;
}

// Drops the points of `d` (and their point data) for which `keep(point)` is false; the
// cells are left as they are.
template <class Keep>
void keep_points(MeshData& d, const Keep& keep) {
  const auto kept = [&](auto& values, std::size_t width) {
    auto at = values.begin();
    for (std::size_t n = 0; n < d.points.size(); ++n)
      if (keep(n)) {
        const auto from = values.begin() + static_cast<std::ptrdiff_t>(n * width);
        at = std::copy(from, from + static_cast<std::ptrdiff_t>(width), at);
      }
    values.erase(at, values.end());
  };
  for (DataArray& a : d.point_data) kept(a.values, static_cast<std::size_t>(a.n_components));
  kept(d.points, 1);
}

// The owned cells of `held` (an unstructured part: its first cells, `block` a list) and the
// nodes they use, with their global ids.
MeshPart owned_cells(MeshData held, const dist::Block& block, std::int64_t whole_cells) {
  MeshPart out;
  out.n_cells = whole_cells;
  const auto npc = static_cast<std::size_t>(held.nodes_per_cell());
  const auto owned = static_cast<std::size_t>(block.owned_cell_end);
  held.cells.resize(owned * npc);
  for (DataArray& a : held.cell_data)
    a.values.resize(owned * static_cast<std::size_t>(a.n_components));
  std::vector<index_t> to(held.points.size(), -1);  // new id of each held node used
  for (const NodeId v : held.cells) to[v.idx()] = 0;
  index_t kept = 0;
  for (std::size_t n = 0; n < to.size(); ++n)
    if (to[n] >= 0) {
      to[n] = kept++;
      out.node_ids.push_back(block.node_ids[n]);
    }
  for (NodeId& v : held.cells) v = NodeId(to[v.idx()]);
  keep_points(held, [&](std::size_t n) { return to[n] >= 0; });
  out.cell_ids.assign(block.cell_ids.begin(),
                      block.cell_ids.begin() + static_cast<std::ptrdiff_t>(owned));
  out.data = std::move(held);
  return out;
}

// Rank 0 holds every rank's piece twice while gathering (the messages, then the whole mesh):
// beyond the limit (none when <= 0) every rank stops before anything travels.
void check_gather_memory(const dist::Communicator& comm, const MeshData& piece, double limit) {
  const double whole = dist::sum_in_rank_order(comm, data_bytes(piece));
  dist::on_every_rank(comm, [&] {
    if (limit > 0 && 2 * whole > limit)
      throw ResourceError("gathering the whole mesh (" + size_text(whole) +
                          ") on rank 0 needs about " + size_text(2 * whole) +
                          ", more than the memory limit " + size_text(limit));
  });
}

/// Rank 0's whole mesh from every rank's piece of a mesh whose pieces share no point: the
/// pieces in rank order, node ids shifted by the points of the ranks before, with rank 0's
/// metadata and array names and types.
MeshData gathered_disjoint(const dist::Communicator& comm, const MeshData& piece) {
  dist::Buffer mine;
  std::vector<double> xyz;
  xyz.reserve(3 * piece.points.size());
  for (const Vec3& p : piece.points) xyz.insert(xyz.end(), p.data(), p.data() + 3);
  mine.put_vector(xyz);
  mine.put(static_cast<std::uint64_t>(piece.cells.size()));
  mine.put_values(piece.cells.data(), piece.cells.size());
  for (const DataArray& a : piece.cell_data) mine.put_vector(a.values);
  for (const DataArray& a : piece.point_data) mine.put_vector(a.values);
  std::vector<dist::Buffer> all = dist::gather(comm, mine, 0);
  MeshData whole;
  if (comm.rank() != 0) return whole;
  whole.dim = piece.dim;
  whole.metadata = piece.metadata;
  whole.cell_data = piece.cell_data;
  whole.point_data = piece.point_data;
  for (DataArray& a : whole.cell_data) a.values.clear();
  for (DataArray& a : whole.point_data) a.values.clear();
  for (dist::Buffer& b : all) {
    const auto shift = static_cast<index_t>(whole.points.size());
    const std::vector<double> p = b.get_vector<double>();
    for (std::size_t i = 0; i + 2 < p.size(); i += 3)
      whole.points.emplace_back(p[i], p[i + 1], p[i + 2]);
    const std::size_t first = whole.cells.size();
    whole.cells.resize(first + b.get<std::uint64_t>());
    b.get_values(whole.cells.data() + first, whole.cells.size() - first);
    for (std::size_t i = first; i < whole.cells.size(); ++i)
      whole.cells[i] = NodeId(whole.cells[i].value() + shift);
    for (auto* arrays : {&whole.cell_data, &whole.point_data})
      for (DataArray& a : *arrays) {
        const std::vector<double> v = b.get_vector<double>();
        a.values.insert(a.values.end(), v.begin(), v.end());
      }
    b = dist::Buffer();  // the received bytes go as soon as they are copied
  }
  return whole;
}

// The rows of `values` (`width` values per item) in the order `order` gives.
template <class T>
std::vector<T> reordered(const std::vector<T>& values, std::size_t width,
                         const std::vector<std::size_t>& order) {
  std::vector<T> out;
  out.reserve(values.size());
  for (const std::size_t i : order)
    out.insert(out.end(), values.begin() + static_cast<std::ptrdiff_t>(i * width),
               values.begin() + static_cast<std::ptrdiff_t>((i + 1) * width));
  return out;
}

// `d` with its cells stably sorted by their value of the cell array `key`, and its points by
// the key of the cells using them (a point no cell uses stays after the one before it).
MeshData in_order_of(MeshData d, const std::string& key) {
  const DataArray* k = d.find_cell_array(key);
  if (k == nullptr || k->n_components != 1)
    throw InternalError("no cell array " + key + " to order the gathered cells by");
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  const std::vector<double> cell_key = k->values;
  std::vector<double> point_key(d.points.size(), -std::numeric_limits<double>::infinity());
  for (std::size_t c = 0; c < cell_key.size(); ++c)
    for (std::size_t v = 0; v < npc; ++v) point_key[d.cells[c * npc + v].idx()] = cell_key[c];
  for (std::size_t p = 1; p < point_key.size(); ++p)
    if (std::isinf(point_key[p])) point_key[p] = point_key[p - 1];
  const auto order_of = [](const std::vector<double>& keys) {
    std::vector<std::size_t> order(keys.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    return order;
  };
  const std::vector<std::size_t> cells = order_of(cell_key), points = order_of(point_key);
  std::vector<index_t> new_id(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) new_id[points[i]] = static_cast<index_t>(i);
  for (NodeId& v : d.cells) v = NodeId(new_id[v.idx()]);
  d.cells = reordered(d.cells, npc, cells);
  d.points = reordered(d.points, 1, points);
  for (DataArray& a : d.cell_data)
    a.values = reordered(a.values, static_cast<std::size_t>(a.n_components), cells);
  for (DataArray& a : d.point_data)
    a.values = reordered(a.values, static_cast<std::size_t>(a.n_components), points);
  return d;
}

// Integer weights for the partitioner from `weights` (per cell of this rank, > 0): each over
// the lightest cell's of the whole mesh, rounded, from 1 to 64, and lower caps where the sum
// over `whole_cells` cells could pass Scotch's 2^31.
std::vector<std::int64_t> integer_weights(const dist::Communicator& comm,
                                          const std::vector<double>& weights,
                                          std::int64_t whole_cells) {
  double lightest = std::numeric_limits<double>::infinity();
  for (const double w : weights)
    if (w > 0) lightest = std::min(lightest, w);
  for (const double w : dist::all_gather_values(comm, std::vector<double>{lightest}))
    lightest = std::min(lightest, w);
  const double cap = std::clamp(
      std::floor(std::ldexp(1.0, 30) / static_cast<double>(std::max<std::int64_t>(1, whole_cells))),
      1.0, 64.0);
  std::vector<std::int64_t> out;
  out.reserve(weights.size());
  for (const double w : weights)
    out.push_back(static_cast<std::int64_t>(std::clamp(std::round(w / lightest), 1.0, cap)));
  return out;
}

}  // namespace

RankInput read_on_ranks(const dist::Communicator& comm, const std::string& path,
                        ReadOptions options, int ghost_layers,
                        const std::vector<double>& layer_weights) {
  RankInput in;
  dist::on_every_rank(comm, [&] {
    if (holds_unstructured_mesh(path))
      throw OptionError(path +
                        ": on several ranks this stage reads structured grids only (.vti .vtr "
                        ".vts, their parallel forms, a structured .vtk): run it on one process");
    in.shape = structured_shape(path, options);
    in.slab = layer_weights.empty() ? dist::structured_slab(in.shape.cells, in.shape.dim,
                                                            comm.rank(), comm.size(), ghost_layers)
                                    : dist::weighted_slab(in.shape.cells, in.shape.dim, comm.rank(),
                                                          comm.size(), ghost_layers, layer_weights);
  });
  const auto axis = static_cast<std::size_t>(in.shape.dim - 1);
  options.layers = {in.slab.first_layer, in.slab.first_layer + in.slab.held[axis]};
  dist::on_every_rank(comm, [&] { in.data = read_mesh(path, options); });
  in.whole_cells = 1;
  for (std::size_t a = 0; a < static_cast<std::size_t>(in.shape.dim); ++a)
    in.whole_cells *= in.shape.cells[a];
  return in;
}

RankPieces read_pieces_on_ranks(const dist::Communicator& comm, const std::string& path,
                                const ReadOptions& options) {
  RankPieces pieces;
  dist::on_every_rank(comm, [&] {
    if (!holds_unstructured_mesh(path))
      throw OptionError(path +
                        ": on several ranks this stage reads unstructured meshes only (.pvtu, "
                        ".vtu, .exo, an unstructured .vtk, .vtm, .pvd): run it on one process");
    if (ends_with(path, ".pvtu")) {
      pieces = read_rank_pieces(path, options, comm.rank(), comm.size());
    } else if (comm.rank() == 0) {
      pieces.file = path;
      pieces.pieces.push_back({path, read_mesh(path, options)});
      pieces.index.push_back(0);
    }
  });
  return pieces;
}

RankInput read_mesh_on_ranks(const dist::Communicator& comm, const std::string& path,
                             const ReadOptions& options, int ghost_layers,
                             const std::vector<double>& layer_weights,
                             const CellWeights& cell_weights) {
  if (!holds_unstructured_mesh(path))
    return read_on_ranks(comm, path, options, ghost_layers, layer_weights);
  RankPieces pieces = read_pieces_on_ranks(comm, path, options);
  // Each collective step whole inside on_every_rank: a rank that fails alone must not leave
  // the others waiting in a collective it skipped.
  MeshPart part;
  dist::on_every_rank(comm, [&] { part = merge_rank_pieces(comm, std::move(pieces), options); });
  dist::on_every_rank(comm, [&] {
    std::vector<int> parts;
    {
      std::vector<std::int64_t> cell_nodes;
      cell_nodes.reserve(part.data.cells.size());
      for (const NodeId v : part.data.cells) cell_nodes.push_back(part.node_ids[v.idx()]);
      dist::DistGraph graph = dist::dual_graph(comm, part.data.nodes_per_cell(), cell_nodes);
      if (cell_weights) graph.weights = integer_weights(comm, cell_weights(part), part.n_cells);
      parts = comm.parts_of(graph);
    }
    part = migrate(comm, std::move(part), parts);
  });
  GhostedPart ghosted;
  dist::on_every_rank(comm, [&] { ghosted = with_ghost_layers(comm, part, ghost_layers); });
  RankInput in;
  in.structured = false;
  in.whole_cells = part.n_cells;
  part = MeshPart();
  in.shape.dim = ghosted.part.data.dim;
  in.slab.block =
      dist::Block::listed(std::move(ghosted.part.cell_ids), ghosted.owned_cells,
                          std::move(ghosted.part.node_ids), std::move(ghosted.owns_node));
  in.data = std::move(ghosted.part.data);
  return in;
}

void drop_next_piece_nodes(MeshData& piece,
                           const std::vector<std::pair<index_t, index_t>>& shared) {
  const auto n = static_cast<index_t>(piece.points.size());
  std::vector<index_t> to(static_cast<std::size_t>(n), -1);
  for (const auto& [mine, next] : shared) {
    if (mine < 0 || mine >= n || next < 0 || to[static_cast<std::size_t>(mine)] >= 0)
      throw InternalError("drop_next_piece_nodes: nodes out of the piece or named twice");
    to[static_cast<std::size_t>(mine)] = next;
  }
  const index_t kept = n - static_cast<index_t>(shared.size());
  std::vector<index_t> renumbered(static_cast<std::size_t>(n));
  index_t at = 0;
  for (index_t v = 0; v < n; ++v) {
    const index_t next = to[static_cast<std::size_t>(v)];
    renumbered[static_cast<std::size_t>(v)] = next >= 0 ? kept + next : at++;
  }
  for (NodeId& v : piece.cells) v = NodeId(renumbered[v.idx()]);
  keep_points(piece, [&](std::size_t v) { return to[v] < 0; });
}

// Every rank's `piece` as a .vtu, and the .pvtu naming them.
void write_pieces(const dist::Communicator& comm, const MeshData& piece, const std::string& path,
                  const WriteOptions& options) {
  // Ranks without cells write no piece; the first rank with cells writes the .pvtu (a rank
  // without any would fail in write_vtu, as one process does).
  const std::vector<std::int64_t> cells = dist::all_gather_values(
      comm, std::vector<std::int64_t>{static_cast<std::int64_t>(piece.n_cells())});
  std::vector<std::string> pieces;
  int first = -1;
  for (int r = 0; r < comm.size(); ++r)
    if (cells[static_cast<std::size_t>(r)] > 0) {
      pieces.push_back(base_name(piece_path(path, r)));
      if (first < 0) first = r;
    }
  dist::on_every_rank(comm, [&] {
    if (piece.n_cells() > 0 || (first < 0 && comm.rank() == 0))
      write_vtu(piece, piece_path(path, comm.rank()), options);
    if (comm.rank() == first) write_pvtu(piece, pieces, path);
  });
}

// write_on_ranks for a part of an unstructured mesh: the gathered mesh is rank 0's, every
// rank's owned cells and their nodes put in place by their global ids (migrate).
void write_mesh_part(const dist::Communicator& comm, MeshData held, const RankInput& input,
                     const std::string& path, bool gather, const WriteOptions& options,
                     double memory_limit) {
  MeshPart owned = owned_cells(std::move(held), input.slab.block, input.whole_cells);
  if (!gather) return write_pieces(comm, owned.data, path, options);
  check_gather_memory(comm, owned.data, memory_limit);
  std::vector<int> to_first(owned.cell_ids.size(), 0);
  const MeshPart whole = migrate(comm, std::move(owned), to_first);
  dist::on_every_rank(comm, [&] {
    if (comm.rank() == 0) write_mesh(whole.data, path, options);
  });
}

void write_disjoint_pieces(const dist::Communicator& comm, const MeshData& piece,
                           const std::string& path, bool gather, const WriteOptions& options,
                           double memory_limit, const std::string& order_by) {
  if (!gather) return write_pieces(comm, piece, path, options);
  check_gather_memory(comm, piece, memory_limit);
  MeshData whole = gathered_disjoint(comm, piece);
  if (comm.rank() == 0 && !order_by.empty()) whole = in_order_of(std::move(whole), order_by);
  dist::on_every_rank(comm, [&] {
    if (comm.rank() == 0) write_mesh(whole, path, options);
  });
}

void write_on_ranks(const dist::Communicator& comm, MeshData held, const RankInput& input,
                    const std::string& path, bool gather, const WriteOptions& options,
                    double memory_limit) {
  if (!input.structured)
    return write_mesh_part(comm, std::move(held), input, path, gather, options, memory_limit);
  keep_layers(held, owned_layers(input.slab, input.shape.dim), path);
  if (gather) {
    check_gather_memory(comm, held, memory_limit);
    MeshData whole = gathered(comm, held, input);
    dist::on_every_rank(comm, [&] {
      if (comm.rank() == 0) write_mesh(whole, path, options);
    });
    return;
  }
  if (ends_with(path, ".pvts")) return write_structured_pieces(comm, held, input, path, options);
  std::vector<std::string> pieces;
  for (int r = 0; r < comm.size(); ++r) pieces.push_back(base_name(piece_path(path, r)));
  dist::on_every_rank(comm, [&] {
    write_vtu(held, piece_path(path, comm.rank()), options);
    if (comm.rank() == 0) write_pvtu(held, pieces, path);
  });
}

}  // namespace hexadapt::io
