// .pvts .pvtr .pvti: pieces with extents inside one WholeExtent, put back into that one
// structured grid. Sizes come from the pieces (read and checked like single files) before
// the whole grid is allocated, so a WholeExtent that lies cannot allocate more than the
// pieces hold.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "../vtk_cells.h"
#include "../vtk_xml/vtk_xml_array.h"
#include "../vtk_xml/vtk_xml_reader.h"
#include "hexadapt/core/error.h"
#include "vtk_collection.h"

namespace hexadapt::io::detail {

namespace {

using Extent = std::array<std::int64_t, 6>;

Extent extent_attribute(const VtkXmlDocument& doc, const pugi::xml_node& e, const char* name) {
  if (!e.attribute(name))
    throw InputError(doc.file, place(e), std::string("no ") + name + " attribute");
  std::array<std::int64_t, 6> v{};
  parse_ascii(e.attribute(name).as_string(), 0, ScalarType::int64, 6, v.data(), doc.file,
              place(e) + " attribute " + name);
  return v;
}

bool empty(const Extent& e) {
  return e[1] < e[0] || e[3] < e[2] || e[5] < e[4];
}

bool inside(const Extent& e, const Extent& whole) {
  for (std::size_t a = 0; a < 3; ++a)
    if (e[2 * a] < whole[2 * a] || e[2 * a + 1] > whole[2 * a + 1]) return false;
  return true;
}

std::string extent_text(const Extent& e) {
  std::string s;
  for (std::size_t k = 0; k < 6; ++k) s += (k ? " " : "") + std::to_string(e[k]);
  return s;
}

struct Lattice {
  std::array<std::size_t, 3> points{1, 1, 1}, cells{1, 1, 1};
  std::size_t n_points() const { return points[0] * points[1] * points[2]; }
  std::size_t n_cells() const { return cells[0] * cells[1] * cells[2]; }
};

Lattice lattice_of(const Extent& e) {
  Lattice l;
  for (std::size_t a = 0; a < 3; ++a) {
    l.points[a] = static_cast<std::size_t>(e[2 * a + 1] - e[2 * a] + 1);
    l.cells[a] = std::max<std::size_t>(l.points[a] - 1, 1);
  }
  return l;
}

// Before any product of sizes is formed: each axis and the point count within 32-bit ids.
void check_whole(const VtkXmlDocument& doc, const pugi::xml_node& dataset, const Extent& whole) {
  if (empty(whole)) throw InputError(doc.file, place(dataset), "empty WholeExtent");
  constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<index_t>::max());
  std::uint64_t n = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    const auto span =
        static_cast<std::uint64_t>(whole[2 * a + 1]) - static_cast<std::uint64_t>(whole[2 * a]) + 1;
    if (span == 0 || span > max || n * span > max)
      throw InputError(doc.file, place(dataset),
                       "WholeExtent " + extent_text(whole) + ": too many points for 32-bit ids");
    n *= span;
  }
}

struct Piece {
  std::string file;
  Extent extent{};
  MeshData data;  ///< points in file order, arrays, no cells
};

Piece read_piece(const VtkXmlDocument& doc, const pugi::xml_node& e, const std::string& type,
                 const CollectionContext& ctx) {
  Piece out;
  out.file = resolve_reference(doc, e, e.attribute("Source").as_string());
  const std::string content = load_reference(doc, e, out.file, ctx);
  VtkXmlDocument piece;
  load_vtk_xml(piece, content, out.file);
  if (piece.type != type)
    throw InputError(doc.file, place(e),
                     "piece " + quote_token(out.file) + " is a " + quote_token(piece.type) +
                         ", expected a " + type + " as the file announces");
  StructuredPiece p = read_structured_piece(piece);
  out.extent = p.extent;
  out.data = std::move(p.data);
  return out;
}

// Where the pieces' data go in the whole grid; checks that every cell is covered.
class Tiler {
 public:
  Tiler(const Extent& whole, const MeshData& first) : whole_(whole), lattice_(lattice_of(whole)) {
    points_.assign(lattice_.n_points(), Vec3::Zero());
    point_set_.assign(lattice_.n_points(), 0);
    cell_set_.assign(lattice_.n_cells(), 0);
    data_.metadata = first.metadata;
    // Ghost flags say which piece owns a cell; the whole grid has no ghosts.
    for (const DataArray& a : first.cell_data)
      if (a.name != ghost_array) data_.cell_data.push_back(a);
    for (const DataArray& a : first.point_data)
      if (a.name != ghost_array) data_.point_data.push_back(a);
    for (DataArray& a : data_.cell_data) a.values.assign(lattice_.n_cells() * comps(a), 0.0);
    for (DataArray& a : data_.point_data) a.values.assign(lattice_.n_points() * comps(a), 0.0);
  }

  void add(const Piece& p, double tolerance, const std::string& file) {
    const Lattice l = lattice_of(p.extent);
    for_each(l.points, [&](std::size_t local, const std::array<std::size_t, 3>& ijk) {
      const std::optional<std::size_t> g = global(ijk, p.extent, lattice_.points);
      if (!g) return;
      const Vec3& x = p.data.points[local];
      if (point_set_[*g] && (points_[*g] - x).norm() > tolerance)
        throw InputError(file, quote_token(p.file),
                         "point " + std::to_string(local) +
                             " is not where the other pieces put the same grid point");
      points_[*g] = x;
      point_set_[*g] = 1;
      for (DataArray& a : data_.point_data) copy(a, *p.data.find_point_array(a.name), local, *g);
    });
    const DataArray* ghost = p.data.find_cell_array(ghost_array);
    for_each(l.cells, [&](std::size_t local, const std::array<std::size_t, 3>& ijk) {
      const std::optional<std::size_t> g = global(ijk, p.extent, lattice_.cells);
      if (!g || cell_set_[*g] || is_ghost_cell(ghost, local)) return;
      cell_set_[*g] = 1;
      for (DataArray& a : data_.cell_data) copy(a, *p.data.find_cell_array(a.name), local, *g);
    });
  }

  // Throws when a cell of the whole extent is in no piece.
  void check_covered(const std::string& file) const {
    const auto it = std::find(cell_set_.begin(), cell_set_.end(), 0);
    if (it == cell_set_.end()) return;
    const auto c = static_cast<std::size_t>(it - cell_set_.begin());
    const std::size_t i = c % lattice_.cells[0], j = c / lattice_.cells[0] % lattice_.cells[1],
                      k = c / lattice_.cells[0] / lattice_.cells[1];
    throw InputError(file, "WholeExtent " + extent_text(whole_),
                     "cell (" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                         std::to_string(k) + ") of the whole extent is in no piece");
  }

  MeshData take() { return std::move(data_); }
  std::vector<Vec3> take_points() { return std::move(points_); }

 private:
  static std::size_t comps(const DataArray& a) { return static_cast<std::size_t>(a.n_components); }

  static void copy(DataArray& to, const DataArray& from, std::size_t local, std::size_t g) {
    const std::size_t n = comps(to);
    std::copy_n(from.values.begin() + static_cast<std::ptrdiff_t>(local * n), n,
                to.values.begin() + static_cast<std::ptrdiff_t>(g * n));
  }

  template <class F>
  static void for_each(const std::array<std::size_t, 3>& n, F&& f) {
    std::size_t local = 0;
    for (std::size_t k = 0; k < n[2]; ++k)
      for (std::size_t j = 0; j < n[1]; ++j)
        for (std::size_t i = 0; i < n[0]; ++i) f(local++, std::array<std::size_t, 3>{i, j, k});
  }

  // The index in the tiled extent of local (i, j, k) of a piece with extent e; none when it
  // lies outside (a window of layers tiles part of the whole extent).
  std::optional<std::size_t> global(const std::array<std::size_t, 3>& ijk, const Extent& e,
                                    const std::array<std::size_t, 3>& n) const {
    std::array<std::size_t, 3> g{};
    for (std::size_t a = 0; a < 3; ++a) {
      const std::int64_t at = static_cast<std::int64_t>(ijk[a]) + e[2 * a] - whole_[2 * a];
      if (at < 0 || at >= static_cast<std::int64_t>(n[a])) return std::nullopt;
      g[a] = static_cast<std::size_t>(at);
    }
    return g[0] + n[0] * (g[1] + n[1] * g[2]);
  }

  Extent whole_;
  Lattice lattice_;
  MeshData data_;
  std::vector<Vec3> points_;
  std::vector<char> point_set_, cell_set_;
};

void check_piece(const VtkXmlDocument& doc, const pugi::xml_node& e, const Piece& p,
                 const Extent& announced, const Piece& first) {
  if (p.extent != announced)
    throw InputError(doc.file, place(e),
                     "Extent " + extent_text(announced) + " but the piece " + quote_token(p.file) +
                         " has " + extent_text(p.extent));
  for (const auto& [mine, theirs] : {std::pair{&p.data.cell_data, &first.data.cell_data},
                                     std::pair{&p.data.point_data, &first.data.point_data}})
    for (const DataArray& a : *theirs) {
      const auto it = std::find_if(mine->begin(), mine->end(),
                                   [&](const DataArray& b) { return b.name == a.name; });
      if (it == mine->end() || it->n_components != a.n_components)
        throw InputError(doc.file, place(e),
                         "piece " + quote_token(p.file) + " has no array " + quote_token(a.name) +
                             " of " + std::to_string(a.n_components) + " components as " +
                             quote_token(first.file) + " has");
    }
}

// The largest distance at which two pieces' copies of a grid point still agree.
double agreement_tolerance(const std::vector<Piece>& pieces, double weld_tolerance) {
  double size = 0;
  for (const Piece& p : pieces)
    for (const Vec3& x : p.data.points) size = std::max(size, x.cwiseAbs().maxCoeff());
  return std::max(weld_tolerance, 1e-12) * std::max(size, 1e-300);
}

// The file axis a window of layers cuts: the last with more than one point.
std::size_t cut_axis(const Extent& whole) {
  std::size_t axis = 0;
  for (std::size_t a = 0; a < 3; ++a)
    if (whole[2 * a + 1] > whole[2 * a]) axis = a;
  return axis;
}

// The part of `whole` that the cell layers [first, end) of its cut axis span.
Extent window_of(const VtkXmlDocument& doc, const Extent& whole, const std::array<int, 2>& layers) {
  const std::size_t a = cut_axis(whole);
  const std::int64_t n = whole[2 * a + 1] - whole[2 * a];
  const auto [first, end] = layers;
  if (first < 0 || end <= first || end > n)
    throw InputError(doc.file, "WholeExtent " + extent_text(whole),
                     "cell layers " + std::to_string(first) + " to " + std::to_string(end) +
                         " are not inside the grid's " + std::to_string(n) + " layers");
  Extent w = whole;
  w[2 * a] = whole[2 * a] + first;
  w[2 * a + 1] = whole[2 * a] + end;
  return w;
}

// The cells of e within w (both point extents).
std::size_t cells_within(const Extent& e, const Extent& w) {
  std::size_t n = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    const std::int64_t lo = std::max(e[2 * a], w[2 * a]), hi = std::min(e[2 * a + 1], w[2 * a + 1]);
    if (w[2 * a + 1] == w[2 * a]) continue;  // a flat axis
    if (hi <= lo) return 0;
    n *= static_cast<std::size_t>(hi - lo);
  }
  return n;
}

}  // namespace

StructuredShape parallel_structured_shape(const VtkXmlDocument& doc) {
  const pugi::xml_node dataset = doc.root.child(doc.type.c_str());
  if (!dataset) throw InputError(doc.file, place(doc.root), "no <" + doc.type + "> element");
  const Extent whole = extent_attribute(doc, dataset, "WholeExtent");
  check_whole(doc, dataset, whole);
  // As fill_structured makes the grid: one flat axis makes it 2D, in the other two axes.
  std::vector<int> cells;
  for (std::size_t a = 0; a < 3; ++a)
    if (whole[2 * a + 1] > whole[2 * a])
      cells.push_back(static_cast<int>(whole[2 * a + 1] - whole[2 * a]));
  if (cells.size() < 2)
    throw InputError(doc.file, place(dataset),
                     "a structured data set with a single row of points has no quads or hexes");
  cells.resize(3, 0);
  return {cells[2] > 0 ? 3 : 2, {cells[0], cells[1], cells[2]}};
}

MeshData read_parallel_structured(const VtkXmlDocument& doc, const CollectionContext& ctx) {
  const pugi::xml_node dataset = doc.root.child(doc.type.c_str());
  if (!dataset) throw InputError(doc.file, place(doc.root), "no <" + doc.type + "> element");
  const std::string type = doc.type.substr(1);  // PRectilinearGrid -> RectilinearGrid
  const Extent whole = extent_attribute(doc, dataset, "WholeExtent");
  check_whole(doc, dataset, whole);
  // With a window of layers, the pieces without a cell in it are not read.
  const Extent tiled = ctx.options.layers ? window_of(doc, whole, *ctx.options.layers) : whole;
  std::vector<Piece> pieces;
  std::size_t piece_cells = 0;
  for (const pugi::xml_node e : dataset.children("Piece")) {
    const Extent announced = extent_attribute(doc, e, "Extent");
    if (empty(announced)) continue;
    if (!inside(announced, whole))
      throw InputError(doc.file, place(e),
                       "Extent " + extent_text(announced) + " is not inside the WholeExtent " +
                           extent_text(whole));
    if (cells_within(announced, tiled) == 0) continue;
    pieces.push_back(read_piece(doc, e, type, ctx));
    check_piece(doc, e, pieces.back(), announced, pieces.front());
    piece_cells += cells_within(announced, tiled);
  }
  if (pieces.empty()) throw InputError(doc.file, place(dataset), "no piece with cells");
  // Pieces inside the whole extent that hold fewer cells than it cannot tile it.
  const Lattice l = lattice_of(tiled);
  if (piece_cells < l.n_cells())
    throw InputError(doc.file, place(dataset),
                     (ctx.options.layers ? "the window of layers read, extent " : "WholeExtent ") +
                         extent_text(tiled) + " has " + std::to_string(l.n_cells()) +
                         " cells but the pieces hold only " + std::to_string(piece_cells));
  Tiler tiler(tiled, pieces.front().data);
  const double tolerance = agreement_tolerance(pieces, ctx.options.weld_tolerance);
  for (const Piece& p : pieces) tiler.add(p, tolerance, doc.file);
  tiler.check_covered(doc.file);
  std::vector<Vec3> points = tiler.take_points();
  MeshData data = tiler.take();
  const std::array<std::int64_t, 3> dims{static_cast<std::int64_t>(l.points[0]),
                                         static_cast<std::int64_t>(l.points[1]),
                                         static_cast<std::int64_t>(l.points[2])};
  fill_structured(data, dims, std::move(points), ctx.options, doc.file);
  return data;
}

}  // namespace hexadapt::io::detail
