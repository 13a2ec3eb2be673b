// Merging the pieces of one mesh (.pvtu pieces, .vtm blocks, .pvd parts): ghost cells out,
// points of different pieces welded within a tolerance relative to the cell size there,
// cells given twice kept once, unused points dropped. Everything follows the pieces' order,
// so the same files always give the same mesh.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../mesh_rows.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/geometry.h"
#include "hexadapt/core/log.h"
#include "hexadapt/dist/merge_pieces.h"
#include "hexadapt/dist/routing.h"
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

void check_same_kind(const NamedMesh& first, const std::vector<NamedMesh>& pieces,
                     const std::string& file) {
  const auto kind = [](int dim) { return dim == 3 ? "hexes" : "quads"; };
  for (const NamedMesh& p : pieces)
    if (p.data.dim != first.data.dim)
      throw InputError(file, quote_token(p.file),
                       std::string("holds ") + kind(p.data.dim) + " but " +
                           quote_token(first.file) + " holds " + kind(first.data.dim) +
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
std::vector<double> shortest_edges(const dist::PiecesPart& d) {
  std::vector<double> h(d.points.size(), std::numeric_limits<double>::infinity());
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell);
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

// The pieces one after another: their points and cells (weld tolerances not set yet), and
// their arrays with the first piece's (`first`) metadata.
struct Concatenated {
  dist::PiecesPart part;
  MeshData data;  ///< no points or cells
};

Concatenated concatenate(std::vector<NamedMesh>& pieces, const std::vector<std::int64_t>& index,
                         const NamedMesh& first, const std::string& file) {
  std::size_t n_points = 0;
  for (const NamedMesh& p : pieces) n_points += p.data.points.size();
  if (n_points > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
    throw InputError(file, "pieces", "too many points together for 32-bit ids");
  Concatenated out;
  dist::PiecesPart& part = out.part;
  MeshData& d = out.data;
  d.dim = first.data.dim;
  d.metadata = first.data.metadata;
  d.cell_data = first.data.cell_data;
  d.point_data = first.data.point_data;
  part.nodes_per_cell = d.nodes_per_cell();
  std::size_t n_nodes = 0;
  for (const NamedMesh& p : pieces) n_nodes += p.data.cells.size();
  part.cells.reserve(n_nodes);
  part.points.reserve(n_points);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    MeshData& p = pieces[k].data;
    const auto offset = static_cast<index_t>(part.points.size());
    for (const NodeId n : p.cells) part.cells.push_back(NodeId(n.value() + offset));
    part.points.insert(part.points.end(), p.points.begin(), p.points.end());
    part.point_piece.resize(part.points.size(), index[k]);
    part.cell_piece.resize(part.cells.size() / static_cast<std::size_t>(part.nodes_per_cell),
                           index[k]);
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

// The merged part's data: the kept cells and their arrays, and the points' rows fetched from
// the ranks holding the input points they come from.
MeshPart merged_part(const dist::Communicator& comm, Concatenated& all, dist::MergedPart& m) {
  MeshData& d = all.data;
  const auto held = all.part.points.size();
  std::vector<double> rows = rows_of(&all.part.points, d.point_data, held);
  all.part = dist::PiecesPart();
  rows = dist::fetch_rows(comm, dist::Ranges::of(comm, static_cast<std::int64_t>(held)), rows,
                          row_width(true, d.point_data), m.node_sources);
  set_rows(rows, m.node_sources.size(), &d.points, d.point_data);
  for (DataArray& a : d.cell_data)
    filter_tuples(a, m.kept.size(), [&](std::size_t c) { return m.kept[c] != 0; });
  d.cells = std::move(m.cells);
  MeshPart out;
  out.data = std::move(d);
  out.node_ids = std::move(m.node_ids);
  out.cell_ids.resize(static_cast<std::size_t>(out.data.n_cells()));
  for (std::size_t c = 0; c < out.cell_ids.size(); ++c)
    out.cell_ids[c] = m.cell_offset + static_cast<std::int64_t>(c);
  out.n_cells = m.n_cells;
  out.n_nodes = m.n_nodes;
  return out;
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

MeshPart merge_on_ranks(const dist::Communicator& comm, std::vector<NamedMesh> pieces,
                        const std::vector<std::int64_t>& index, double weld_tolerance,
                        const std::string& file) {
  if (!(weld_tolerance >= 0))
    throw OptionError("weld tolerance " + std::to_string(weld_tolerance) + ": expected >= 0");
  std::int64_t ghosts = 0;
  for (NamedMesh& p : pieces) {
    ghosts += drop_ghost_cells(p.data);
    p.data.structured_cells = {0, 0, 0};
  }
  const NamedMesh first = first_piece_header(comm, pieces, file);
  agree_on_input_errors(comm, [&] { check_same_kind(first, pieces, file); });
  agree_on_input_errors(comm, [&] {
    for (const NamedMesh& p : pieces) {
      check_same_arrays(first.data.cell_data, p.data.cell_data, first.file, p.file, "cell", file);
      check_same_arrays(first.data.point_data, p.data.point_data, first.file, p.file, "point",
                        file);
    }
  });
  const auto n_pieces = dist::sum_in_rank_order(comm, static_cast<std::int64_t>(pieces.size()));
  Concatenated all = concatenate(pieces, index, first, file);
  all.part.tolerance = shortest_edges(all.part);
  for (double& t : all.part.tolerance) t *= weld_tolerance;
  dist::MergedPart m = dist::merge_pieces(comm, all.part);
  log_info(file + ": " + std::to_string(n_pieces) + " pieces merged: " + std::to_string(m.welded) +
           " points welded, " + std::to_string(dist::sum_in_rank_order(comm, ghosts)) +
           " ghost cells and " + std::to_string(m.repeated) + " repeated cells dropped");
  return merged_part(comm, all, m);
}

MeshData merge_pieces(std::vector<NamedMesh> pieces, double weld_tolerance,
                      const std::string& file) {
  std::vector<std::int64_t> index(pieces.size());
  for (std::size_t k = 0; k < index.size(); ++k) index[k] = static_cast<std::int64_t>(k);
  return merge_on_ranks(dist::serial(), std::move(pieces), index, weld_tolerance, file).data;
}

}  // namespace hexadapt::io::detail
