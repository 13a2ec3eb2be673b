// Merging the pieces of one mesh (.pvtu pieces, .vtm blocks, .pvd parts): ghost cells out,
// points of different pieces welded within a tolerance relative to the cell size there,
// cells given twice kept once, unused points dropped. Everything follows the pieces' order,
// so the same files always give the same mesh.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"
#include "hexadapt/core/geometry.h"
#include "hexadapt/core/log.h"
#include "vtk_collection.h"

namespace hexadapt::io::detail {

namespace {

// VTK's vtkGhostType bit of a cell that another piece owns.
constexpr int duplicate_cell_bit = 1;

template <class Keep>
void filter_tuples(DataArray& a, std::size_t n, Keep&& keep) {
  const auto nc = static_cast<std::size_t>(a.n_components);
  std::size_t out = 0;
  for (std::size_t t = 0; t < n; ++t)
    if (keep(t)) {
      for (std::size_t c = 0; c < nc; ++c) a.values[out * nc + c] = a.values[t * nc + c];
      ++out;
    }
  a.values.resize(out * nc);
}

void remove_array(std::vector<DataArray>& arrays, const std::string& name) {
  arrays.erase(std::remove_if(arrays.begin(), arrays.end(),
                              [&](const DataArray& a) { return a.name == name; }),
               arrays.end());
}

void check_same_kind(const std::vector<NamedMesh>& pieces, const std::string& file) {
  const auto kind = [](int dim) { return dim == 3 ? "hexes" : "quads"; };
  for (const NamedMesh& p : pieces)
    if (p.data.dim != pieces.front().data.dim)
      throw InputError(file, quote_token(p.file),
                       std::string("holds ") + kind(p.data.dim) + " but " +
                           quote_token(pieces.front().file) + " holds " +
                           kind(pieces.front().data.dim) +
                           ": the pieces and blocks of one mesh hold one kind of cell");
}

void check_same_arrays(const std::vector<DataArray>& first, const std::vector<DataArray>& other,
                       const std::string& first_file, const std::string& other_file,
                       const char* kind, const std::string& file) {
  for (const DataArray& a : first) {
    const auto it = std::find_if(other.begin(), other.end(),
                                 [&](const DataArray& b) { return b.name == a.name; });
    if (it == other.end() || it->n_components != a.n_components)
      throw InputError(file, quote_token(other_file),
                       std::string("has no ") + kind + " array " + quote_token(a.name) + " of " +
                           std::to_string(a.n_components) + " components as " +
                           quote_token(first_file) + " has");
  }
  if (other.size() != first.size())
    for (const DataArray& b : other)
      check_same_arrays({b}, first, other_file, first_file, kind, file);
}

// The shortest positive edge at each point (0 at points of no cell).
std::vector<double> shortest_edges(const MeshData& d) {
  std::vector<double> h(d.points.size(), std::numeric_limits<double>::infinity());
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  const auto visit = [&](NodeId a, NodeId b) {
    const double l = (d.points[a.idx()] - d.points[b.idx()]).norm();
    if (l <= 0) return;
    h[a.idx()] = std::min(h[a.idx()], l);
    h[b.idx()] = std::min(h[b.idx()], l);
  };
  for (std::size_t c = 0; c < d.cells.size() / npc; ++c) {
    const NodeId* n = d.cells.data() + c * npc;
    if (npc == 4)  // cells in kernel order: a quad's faces are its edges
      for (const auto& e : ref_quad::face_nodes) visit(n[e[0]], n[e[1]]);
    else
      for (const auto& e : ref_hex::edges) visit(n[e[0]], n[e[1]]);
  }
  for (double& x : h)
    if (!std::isfinite(x)) x = 0;
  return h;
}

using Key = std::array<std::int64_t, 3>;

// rep[q]: the first point (in order) of another piece within the tolerance of q, or q.
std::vector<std::size_t> weld(const std::vector<Vec3>& points, const std::vector<int>& piece,
                              const std::vector<double>& tol) {
  std::vector<std::size_t> rep(points.size());
  for (std::size_t q = 0; q < rep.size(); ++q) rep[q] = q;
  double max_tol = 0;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t q = 0; q < points.size(); ++q) {
    max_tol = std::max(max_tol, tol[q]);
    lo = lo.cwiseMin(points[q]);
    hi = hi.cwiseMax(points[q]);
  }
  if (max_tol <= 0) return rep;
  // Buckets twice the largest tolerance: a point's neighbourhood spans <= 2 per axis. Keys
  // stay well inside 64 bits (a tolerance below the grid's size / 2^52 is not resolvable).
  const double g = std::max(2 * max_tol, (hi - lo).maxCoeff() / 4503599627370496.0);
  const auto key_of = [&](const Vec3& p, int a, double shift) {
    return static_cast<std::int64_t>(std::floor((p[a] + shift - lo[a]) / g));
  };
  std::vector<std::pair<Key, std::size_t>> sorted;
  sorted.reserve(points.size());
  for (std::size_t q = 0; q < points.size(); ++q)
    if (tol[q] > 0)
      sorted.push_back(
          {{key_of(points[q], 0, 0), key_of(points[q], 1, 0), key_of(points[q], 2, 0)}, q});
  std::sort(sorted.begin(), sorted.end());
  for (const auto& [unused, q] : sorted) {
    (void)unused;
    Key from, to;
    for (int a = 0; a < 3; ++a) {
      from[static_cast<std::size_t>(a)] = key_of(points[q], a, -tol[q]);
      to[static_cast<std::size_t>(a)] = key_of(points[q], a, tol[q]);
    }
    std::size_t best = q;
    for (std::int64_t i = from[0]; i <= to[0]; ++i)
      for (std::int64_t j = from[1]; j <= to[1]; ++j)
        for (std::int64_t k = from[2]; k <= to[2]; ++k) {
          const Key key{i, j, k};
          auto it =
              std::lower_bound(sorted.begin(), sorted.end(), std::pair<Key, std::size_t>{key, 0});
          for (; it != sorted.end() && it->first == key; ++it) {
            const std::size_t p = it->second;
            if (p < best && piece[p] != piece[q] &&
                (points[p] - points[q]).norm() <= std::min(tol[p], tol[q]))
              best = p;
          }
        }
    rep[q] = best;
  }
  // Chains (q -> p -> an earlier p') end at the first point: follow them in order.
  for (std::size_t q = 0; q < rep.size(); ++q) rep[q] = rep[rep[q]];
  return rep;
}

struct Concatenated {
  MeshData data;
  std::vector<int> point_piece, cell_piece;
};

Concatenated concatenate(std::vector<NamedMesh>& pieces, const std::string& file) {
  std::size_t n_points = 0;
  for (const NamedMesh& p : pieces) n_points += p.data.points.size();
  if (n_points > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
    throw InputError(file, "pieces", "too many points together for 32-bit ids");
  Concatenated out;
  MeshData& d = out.data;
  d.dim = pieces.front().data.dim;
  d.metadata = pieces.front().data.metadata;
  d.cell_data = pieces.front().data.cell_data;
  d.point_data = pieces.front().data.point_data;
  for (DataArray& a : d.cell_data) a.values.clear();
  for (DataArray& a : d.point_data) a.values.clear();
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    MeshData& p = pieces[k].data;
    const auto offset = static_cast<index_t>(d.points.size());
    for (const NodeId n : p.cells) d.cells.push_back(NodeId(n.value() + offset));
    d.points.insert(d.points.end(), p.points.begin(), p.points.end());
    out.point_piece.resize(d.points.size(), static_cast<int>(k));
    out.cell_piece.resize(static_cast<std::size_t>(d.n_cells()), static_cast<int>(k));
    for (DataArray& a : d.cell_data) {
      const DataArray* b = p.find_cell_array(a.name);
      a.values.insert(a.values.end(), b->values.begin(), b->values.end());
    }
    for (DataArray& a : d.point_data) {
      const DataArray* b = p.find_point_array(a.name);
      a.values.insert(a.values.end(), b->values.begin(), b->values.end());
    }
    p = MeshData();
  }
  return out;
}

// Cells whose nodes (as a set) an earlier cell of another piece already has.
std::vector<char> repeated_cells(const MeshData& d, const std::vector<int>& cell_piece) {
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  const auto n = static_cast<std::size_t>(d.n_cells());
  std::vector<std::pair<std::array<index_t, 8>, std::size_t>> keys(n);
  for (std::size_t c = 0; c < n; ++c) {
    std::array<index_t, 8> k{};
    for (std::size_t v = 0; v < npc; ++v) k[v] = d.cells[c * npc + v].value();
    std::sort(k.begin(), k.begin() + static_cast<std::ptrdiff_t>(npc));
    keys[c] = {k, c};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> repeated(n, 0);
  std::size_t first = 0;  // the start of the run of equal keys (the earliest such cell)
  for (std::size_t i = 1; i < n; ++i) {
    if (keys[i].first != keys[first].first) first = i;
    if (first < i && cell_piece[keys[first].second] != cell_piece[keys[i].second])
      repeated[keys[i].second] = 1;
  }
  return repeated;
}

// Keeps the cells not flagged and the points they use, renumbered in order.
void compact(MeshData& d, const std::vector<char>& drop_cell) {
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  const std::size_t n_cells = drop_cell.size();
  std::vector<NodeId> cells;
  std::vector<char> used(d.points.size(), 0);
  for (std::size_t c = 0; c < n_cells; ++c)
    if (!drop_cell[c])
      for (std::size_t v = 0; v < npc; ++v) {
        cells.push_back(d.cells[c * npc + v]);
        used[d.cells[c * npc + v].idx()] = 1;
      }
  std::vector<index_t> number(d.points.size(), -1);
  std::vector<Vec3> points;
  for (std::size_t p = 0; p < d.points.size(); ++p)
    if (used[p]) {
      number[p] = static_cast<index_t>(points.size());
      points.push_back(d.points[p]);
    }
  for (NodeId& n : cells) n = NodeId(number[n.idx()]);
  for (DataArray& a : d.cell_data)
    filter_tuples(a, n_cells, [&](std::size_t c) { return !drop_cell[c]; });
  for (DataArray& a : d.point_data)
    filter_tuples(a, d.points.size(), [&](std::size_t p) { return used[p] != 0; });
  d.cells = std::move(cells);
  d.points = std::move(points);
}

}  // namespace

bool is_ghost_cell(const DataArray* ghost, std::size_t c) {
  if (!ghost || ghost->n_components != 1) return false;
  const double v = ghost->values[c];
  return v >= 0 && v < 256 && (static_cast<int>(v) & duplicate_cell_bit) != 0;
}

index_t drop_ghost_cells(MeshData& data) {
  const DataArray* ghost = data.find_cell_array(ghost_array);
  index_t dropped = 0;
  const auto n = static_cast<std::size_t>(data.n_cells());
  std::vector<char> drop(n, 0);
  for (std::size_t c = 0; c < n; ++c)
    if (is_ghost_cell(ghost, c)) {
      drop[c] = 1;
      ++dropped;
    }
  if (dropped > 0) compact(data, drop);
  remove_array(data.cell_data, ghost_array);
  remove_array(data.point_data, ghost_array);
  return dropped;
}

MeshData merge_pieces(std::vector<NamedMesh> pieces, double weld_tolerance,
                      const std::string& file) {
  if (!(weld_tolerance >= 0))
    throw OptionError("weld tolerance " + std::to_string(weld_tolerance) + ": expected >= 0");
  index_t ghosts = 0;
  for (NamedMesh& p : pieces) {
    ghosts += drop_ghost_cells(p.data);
    p.data.structured_cells = {0, 0, 0};
  }
  check_same_kind(pieces, file);
  for (const NamedMesh& p : pieces) {
    check_same_arrays(pieces.front().data.cell_data, p.data.cell_data, pieces.front().file, p.file,
                      "cell", file);
    check_same_arrays(pieces.front().data.point_data, p.data.point_data, pieces.front().file,
                      p.file, "point", file);
  }
  const std::size_t n_pieces = pieces.size();
  Concatenated all = concatenate(pieces, file);
  MeshData& d = all.data;
  std::vector<double> tol = shortest_edges(d);
  for (double& t : tol) t *= weld_tolerance;
  const std::vector<std::size_t> rep = weld(d.points, all.point_piece, tol);
  std::size_t welded = 0;
  for (std::size_t q = 0; q < rep.size(); ++q) welded += rep[q] != q;
  for (NodeId& n : d.cells) n = NodeId(static_cast<index_t>(rep[n.idx()]));
  const std::vector<char> repeated = repeated_cells(d, all.cell_piece);
  const auto n_repeated = std::count(repeated.begin(), repeated.end(), 1);
  compact(d, repeated);
  log_info(file + ": " + std::to_string(n_pieces) + " pieces merged: " + std::to_string(welded) +
           " points welded, " + std::to_string(ghosts) + " ghost cells and " +
           std::to_string(n_repeated) + " repeated cells dropped");
  return std::move(all.data);
}

}  // namespace hexadapt::io::detail
