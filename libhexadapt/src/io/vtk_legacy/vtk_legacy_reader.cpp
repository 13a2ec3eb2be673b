// Legacy VTK reader: header, data set geometry, then the attribute sections
// (legacy_attributes.cpp). Cells are built by the helpers shared with the XML reader.
#include <array>
#include <limits>
#include <string>

#include "../vtk_cells.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/legacy_scanner.h"
#include "hexadapt/io/vtk_legacy.h"
#include "legacy_attributes.h"

namespace hexadapt::io {

namespace {

enum class Kind { points, rectilinear, structured, unstructured };

struct Geometry {
  Kind kind = Kind::unstructured;
  std::array<std::int64_t, 3> dims{0, 0, 0};
  bool have_dims = false;
  Vec3 origin = Vec3::Zero(), spacing = Vec3::Ones();
  std::vector<Vec3> points;
  bool have_points = false;
  std::array<std::vector<double>, 3> coords;
  std::array<bool, 3> have_coords{false, false, false};
  std::vector<std::int64_t> offsets, connectivity, types;
  bool have_cells = false, have_types = false;
};

std::int64_t n_structured_points(const LegacyScanner& s, const Geometry& g) {
  std::int64_t n = 1;
  for (std::int64_t d : g.dims) {
    n *= d;
    if (n > max_legacy_id) s.fail("DIMENSIONS give more points than 32-bit ids can number");
  }
  return n;
}

void read_dimensions(LegacyScanner& s, Geometry& g) {
  for (auto& d : g.dims) d = s.integer("a dimension", 1, max_legacy_id);
  g.have_dims = true;
  n_structured_points(s, g);
}

Vec3 read_vec3(LegacyScanner& s, const char* what) {
  Vec3 v;
  for (int a = 0; a < 3; ++a) v[a] = s.real(what);
  return v;
}

void read_points(LegacyScanner& s, Geometry& g) {
  const std::size_t at = s.mark();
  const auto n = s.integer("a number of points", 0, max_legacy_id);
  if (g.kind == Kind::structured && g.have_dims && n != n_structured_points(s, g))
    s.fail_at(at, "POINTS " + std::to_string(n) + " does not match DIMENSIONS (" +
                      std::to_string(n_structured_points(s, g)) + " points)");
  const LegacyType& t = s.data_type();
  const auto xyz = s.reals(t, 3 * static_cast<std::size_t>(n), "point coordinates");
  g.points.resize(static_cast<std::size_t>(n));
  for (std::size_t p = 0; p < g.points.size(); ++p)
    g.points[p] = Vec3(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);
  g.have_points = true;
}

void read_coordinates(LegacyScanner& s, Geometry& g, int axis) {
  const std::size_t at = s.mark();
  const auto n = s.integer("a number of coordinates", 1, max_legacy_id);
  if (!g.have_dims) s.fail_at(at, "coordinates before DIMENSIONS");
  if (n != g.dims[static_cast<std::size_t>(axis)])
    s.fail_at(at, "expected " + std::to_string(g.dims[static_cast<std::size_t>(axis)]) +
                      " coordinates (DIMENSIONS), found " + std::to_string(n));
  g.coords[static_cast<std::size_t>(axis)] =
      s.reals(s.data_type(), static_cast<std::size_t>(n), "coordinates");
  g.have_coords[static_cast<std::size_t>(axis)] = true;
}

// Classic layout: "CELLS n size" then, per cell, its node count and node ids (32-bit ints).
void read_classic_cells(LegacyScanner& s, Geometry& g, std::int64_t n, std::int64_t size) {
  static constexpr LegacyType kInt{"int", ScalarType::int32, 4, false};
  const std::size_t at = s.position();
  const auto list = s.integers(kInt, static_cast<std::size_t>(size), "cell list entries");
  g.offsets.assign(1, 0);
  g.connectivity.clear();
  std::size_t k = 0;
  for (std::int64_t c = 0; c < n; ++c) {
    if (k >= list.size() || list[k] < 0 || list[k] > size - static_cast<std::int64_t>(k) - 1)
      s.fail_at(at, "cell " + std::to_string(c) + " does not fit in the CELLS size " +
                        std::to_string(size));
    const auto n_nodes = static_cast<std::size_t>(list[k]);
    g.connectivity.insert(g.connectivity.end(), list.begin() + static_cast<std::ptrdiff_t>(k + 1),
                          list.begin() + static_cast<std::ptrdiff_t>(k + 1 + n_nodes));
    k += 1 + n_nodes;
    g.offsets.push_back(static_cast<std::int64_t>(g.connectivity.size()));
  }
  if (k != list.size())
    s.fail_at(at, "CELLS size is " + std::to_string(size) + " but its " + std::to_string(n) +
                      " cells use " + std::to_string(k) + " entries");
}

// VTK 9 layout (file version 5.x): "CELLS n_offsets n_connectivity", OFFSETS, CONNECTIVITY.
void read_offset_cells(LegacyScanner& s, Geometry& g, std::int64_t n_off, std::int64_t m) {
  auto block = [&](const char* keyword, std::int64_t count) {
    const std::size_t at = s.mark();
    if (!keyword_is(s.token(), keyword)) s.fail_at(at, std::string("expected ") + keyword);
    return s.integers(s.data_type(), static_cast<std::size_t>(count), keyword);
  };
  const std::size_t at = s.mark();
  g.offsets = block("OFFSETS", n_off);
  g.connectivity = block("CONNECTIVITY", m);
  if (g.offsets.empty()) g.offsets.assign(1, 0);
  bool ok = g.offsets.front() == 0 && g.offsets.back() == m;
  for (std::size_t c = 1; ok && c < g.offsets.size(); ++c) ok = g.offsets[c] >= g.offsets[c - 1];
  if (!ok)
    s.fail_at(at, "OFFSETS must start at 0, never decrease and end at the CONNECTIVITY size " +
                      std::to_string(m));
}

void read_cells(LegacyScanner& s, Geometry& g) {
  const auto n = s.integer("a number of cells", 0, max_legacy_id);
  const auto size = s.integer("a cell list size", 0, INT64_MAX);
  // The 5.x layout is recognised by its OFFSETS line rather than by the version number.
  if (keyword_is(s.peek_token(), "OFFSETS"))
    read_offset_cells(s, g, n, size);
  else
    read_classic_cells(s, g, n, size);
  g.have_cells = true;
}

void read_cell_types(LegacyScanner& s, Geometry& g) {
  static constexpr LegacyType kInt{"int", ScalarType::int32, 4, false};
  const std::size_t at = s.mark();
  const auto n = s.integer("a number of cell types", 0, max_legacy_id);
  if (!g.have_cells) s.fail_at(at, "CELL_TYPES before CELLS");
  const auto n_cells = static_cast<std::int64_t>(g.offsets.size()) - 1;
  if (n != n_cells)
    s.fail_at(at, "CELL_TYPES " + std::to_string(n) + " does not match the " +
                      std::to_string(n_cells) + " cells of CELLS");
  g.types = s.integers(kInt, static_cast<std::size_t>(n), "cell types");
  g.have_types = true;
}

// True when the keyword was part of the geometry of this kind of data set.
bool read_geometry_keyword(LegacyScanner& s, Geometry& g, std::string_view key) {
  const bool structured = g.kind != Kind::unstructured;
  if (structured && keyword_is(key, "DIMENSIONS")) {
    read_dimensions(s, g);
  } else if (g.kind == Kind::points && keyword_is(key, "ORIGIN")) {
    g.origin = read_vec3(s, "an origin coordinate");
  } else if (g.kind == Kind::points &&
             (keyword_is(key, "SPACING") || keyword_is(key, "ASPECT_RATIO"))) {
    g.spacing = read_vec3(s, "a spacing");
  } else if ((g.kind == Kind::structured || g.kind == Kind::unstructured) &&
             keyword_is(key, "POINTS")) {
    read_points(s, g);
  } else if (g.kind == Kind::rectilinear && keyword_is(key, "X_COORDINATES")) {
    read_coordinates(s, g, 0);
  } else if (g.kind == Kind::rectilinear && keyword_is(key, "Y_COORDINATES")) {
    read_coordinates(s, g, 1);
  } else if (g.kind == Kind::rectilinear && keyword_is(key, "Z_COORDINATES")) {
    read_coordinates(s, g, 2);
  } else if (g.kind == Kind::unstructured && keyword_is(key, "CELLS")) {
    read_cells(s, g);
  } else if (g.kind == Kind::unstructured && keyword_is(key, "CELL_TYPES")) {
    read_cell_types(s, g);
  } else {
    return false;
  }
  return true;
}

std::vector<Vec3> lattice_points(const Geometry& g) {
  std::vector<Vec3> pts;
  const auto& d = g.dims;
  pts.reserve(static_cast<std::size_t>(d[0] * d[1] * d[2]));
  for (std::int64_t k = 0; k < d[2]; ++k)
    for (std::int64_t j = 0; j < d[1]; ++j)
      for (std::int64_t i = 0; i < d[0]; ++i) {
        if (g.kind == Kind::points)
          pts.push_back(g.origin +
                        Vec3(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k))
                            .cwiseProduct(g.spacing));
        else
          pts.emplace_back(g.coords[0][static_cast<std::size_t>(i)],
                           g.coords[1][static_cast<std::size_t>(j)],
                           g.coords[2][static_cast<std::size_t>(k)]);
      }
  return pts;
}

void build_unstructured(LegacyScanner& s, Geometry& g, MeshData& data, const ReadOptions& options) {
  if (g.have_cells && !g.have_types) s.fail("CELLS without CELL_TYPES");
  if (!g.have_points) s.fail("an UNSTRUCTURED_GRID needs POINTS");
  data.points = std::move(g.points);
  for (std::size_t c = 0; c < g.types.size(); ++c) {
    const auto begin = static_cast<std::size_t>(g.offsets[c]);
    const auto count = static_cast<std::size_t>(g.offsets[c + 1]) - begin;
    detail::append_vtk_cell(data, static_cast<int>(g.types[c]), g.connectivity.data() + begin,
                            count, static_cast<std::int64_t>(c), s.file());
  }
  detail::finish_unstructured(data, options, s.file());
}

void build_geometry(LegacyScanner& s, Geometry& g, MeshData& data, const ReadOptions& options) {
  if (g.kind == Kind::unstructured) return build_unstructured(s, g, data, options);
  if (!g.have_dims) s.fail("a structured data set needs DIMENSIONS before its data");
  if (g.kind == Kind::rectilinear && !(g.have_coords[0] && g.have_coords[1] && g.have_coords[2]))
    s.fail("a RECTILINEAR_GRID needs X_COORDINATES, Y_COORDINATES and Z_COORDINATES");
  if (g.kind == Kind::structured && !g.have_points) s.fail("a STRUCTURED_GRID needs POINTS");
  // A lattice is generated, not read: millions of points announced in a file too small to
  // hold any array for them are a lie (or nothing to work on), refused before allocating.
  const std::int64_t n = n_structured_points(s, g);
  if (g.kind != Kind::structured && n > (1 << 20) &&
      static_cast<std::size_t>(n / 8) > s.remaining())
    s.fail("DIMENSIONS announce " + std::to_string(n) + " points but only " +
           std::to_string(s.remaining()) + " bytes of data follow");
  std::vector<Vec3> pts = g.kind == Kind::structured ? std::move(g.points) : lattice_points(g);
  detail::fill_structured(data, g.dims, std::move(pts), options, s.file());
}

Kind read_header(LegacyScanner& s, MeshData& data) {
  const std::string_view magic = s.line();
  if (magic.size() < 14 || !keyword_is(magic.substr(0, 14), "# vtk DataFile"))
    s.fail_at(0, "not a legacy VTK file (expected '# vtk DataFile Version x.x' on line 1)");
  const std::string title(s.line());
  if (!title.empty()) data.metadata.emplace_back("title", title);
  const std::size_t at = s.mark();
  const std::string_view mode = s.token();
  if (keyword_is(mode, "BINARY"))
    s.set_binary(true);
  else if (!keyword_is(mode, "ASCII"))
    s.fail_at(at, "expected ASCII or BINARY on line 3, found " + quote_token(mode));
  const std::size_t at_set = s.mark();
  if (!keyword_is(s.token(), "DATASET")) s.fail_at(at_set, "expected DATASET");
  const std::size_t at_kind = s.mark();
  const std::string_view kind = s.expect_token("a data set type");
  if (keyword_is(kind, "STRUCTURED_POINTS")) return Kind::points;
  if (keyword_is(kind, "RECTILINEAR_GRID")) return Kind::rectilinear;
  if (keyword_is(kind, "STRUCTURED_GRID")) return Kind::structured;
  if (keyword_is(kind, "UNSTRUCTURED_GRID")) return Kind::unstructured;
  s.fail_at(at_kind, "unsupported data set type " + quote_token(kind) +
                         " (expected STRUCTURED_POINTS, RECTILINEAR_GRID, STRUCTURED_GRID or "
                         "UNSTRUCTURED_GRID)");
}

}  // namespace

MeshData read_vtk_legacy(std::string_view content, const std::string& file,
                         const ReadOptions& options) {
  LegacyScanner s(content, file);
  MeshData data;
  Geometry g;
  g.kind = read_header(s, data);
  while (!s.at_end()) {
    const std::size_t at = s.mark();
    const std::string_view key = s.peek_token();
    if (keyword_is(key, "CELL_DATA") || keyword_is(key, "POINT_DATA")) break;
    s.token();
    if (read_geometry_keyword(s, g, key)) continue;
    if (keyword_is(key, "FIELD"))
      detail::read_dataset_field(s, data);
    else if (keyword_is(key, "METADATA"))
      s.skip_block();
    else
      s.fail_at(at, "unknown or misplaced keyword " + quote_token(key) +
                        " in the geometry of the data set");
  }
  build_geometry(s, g, data, options);
  detail::read_attributes(s, data);
  return data;
}

}  // namespace hexadapt::io
