// Reading the model file written by write_model_vtk (model_io.h): an ASCII legacy POLYDATA
// with the material names in the title line and the kind / material_lo / material_hi cell
// arrays. Only this writer's layout is accepted; anything else fails with the line.
#include <fstream>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/legacy_scanner.h"
#include "hexadapt/reconstruct/model_io.h"
#include "model_title.h"

namespace hexadapt::reconstruct {

namespace {

using io::keyword_is;
using io::LegacyScanner;

constexpr std::string_view title_prefix = "hexadapt interface model; materials:";

struct Cells {
  std::vector<std::vector<index_t>> nodes;  // vertices, lines, polygons in that order
  std::size_t n_vertices = 0, n_lines = 0;
};

void read_header(LegacyScanner& in, ModelFile& out) {
  if (in.line().rfind("# vtk DataFile", 0) != 0) in.fail("expected '# vtk DataFile' on line 1");
  const std::size_t at = in.position();
  const std::string title(in.line());
  if (title.rfind(title_prefix, 0) != 0)
    in.fail_at(at, "expected the title '" + std::string(title_prefix) +
                       " ...' of a geometric model (written by write_model_vtk)");
  std::istringstream names(title.substr(title_prefix.size()));
  for (std::string n; names >> n;) out.materials.push_back(detail::name_from_title(n));
  if (!keyword_is(in.expect_token("ASCII"), "ASCII")) in.fail("expected ASCII");
  if (!keyword_is(in.expect_token("DATASET"), "DATASET") ||
      !keyword_is(in.expect_token("POLYDATA"), "POLYDATA"))
    in.fail("expected DATASET POLYDATA");
}

void read_points(LegacyScanner& in, InterfaceModel& m) {
  if (!keyword_is(in.expect_token("POINTS"), "POINTS")) in.fail("expected POINTS");
  const auto n = static_cast<std::size_t>(in.integer("point count", 0, INT32_MAX));
  const auto& type = in.data_type();
  const std::vector<double> xyz = in.reals(type, 3 * n, "point coordinates");
  m.points.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    m.points[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
}

// One VERTICES / LINES / POLYGONS block of cells with `size` nodes each.
void read_block(LegacyScanner& in, std::size_t size, std::size_t n_points, Cells& cells) {
  const auto n = static_cast<std::size_t>(in.integer("cell count", 0, INT32_MAX));
  const auto total = static_cast<std::size_t>(in.integer("connectivity size", 0, INT64_MAX));
  if (total != n * (size + 1)) in.fail("expected " + std::to_string(n * (size + 1)) + " entries");
  for (std::size_t c = 0; c < n; ++c) {
    if (static_cast<std::size_t>(in.integer("cell size")) != size)
      in.fail("expected cells of " + std::to_string(size) + " points");
    std::vector<index_t> v;
    for (std::size_t k = 0; k < size; ++k)
      v.push_back(
          static_cast<index_t>(in.integer("point id", 0, static_cast<std::int64_t>(n_points) - 1)));
    cells.nodes.push_back(std::move(v));
  }
}

Cells read_cells(LegacyScanner& in, std::size_t n_points) {
  Cells cells;
  const char* order[] = {"VERTICES", "LINES", "POLYGONS"};
  const std::size_t sizes[] = {1, 2, 4};
  std::size_t next = 0;
  while (!in.at_end() && !keyword_is(in.peek_token(), "CELL_DATA")) {
    const std::string_view key = in.expect_token("VERTICES, LINES, POLYGONS or CELL_DATA");
    std::size_t k = next;
    while (k < 3 && !keyword_is(key, order[k])) ++k;
    if (k == 3) in.fail("unexpected '" + std::string(key) + "'");
    read_block(in, sizes[k], n_points, cells);
    if (k == 0) cells.n_vertices = cells.nodes.size();
    if (k == 1) cells.n_lines = cells.nodes.size() - cells.n_vertices;
    next = k + 1;
  }
  return cells;
}

std::vector<std::int64_t> read_arrays(LegacyScanner& in, std::size_t n, const char* name) {
  // The FIELD block holds material_lo, material_hi, kind in that order.
  const std::string_view got = in.expect_token(name);
  if (got != name) in.fail("expected the array " + std::string(name));
  if (in.integer("components", 1, 1) != 1 || static_cast<std::size_t>(in.integer("tuples")) != n)
    in.fail("expected " + std::string(name) + " 1 " + std::to_string(n));
  const auto& type = in.data_type();
  return in.integers(type, n, name);
}

void build(LegacyScanner& in, const Cells& cells, InterfaceModel& m) {
  const std::size_t n = cells.nodes.size();
  std::vector<std::int64_t> lo, hi, kind;
  if (n > 0) {
    if (!keyword_is(in.expect_token("CELL_DATA"), "CELL_DATA") ||
        static_cast<std::size_t>(in.integer("cell count")) != n)
      in.fail("expected CELL_DATA " + std::to_string(n));
    if (!keyword_is(in.expect_token("FIELD"), "FIELD")) in.fail("expected FIELD");
    in.expect_token("field name");
    if (in.integer("array count") != 3) in.fail("expected 3 arrays");
    lo = read_arrays(in, n, "material_lo");
    hi = read_arrays(in, n, "material_hi");
    kind = read_arrays(in, n, "kind");
  }
  const bool has_polygons = n > cells.n_vertices + cells.n_lines;
  m.dim = has_polygons ? 3 : 0;
  for (std::size_t c = 0; c < n; ++c) {
    const auto& v = cells.nodes[c];
    if (kind[c] == 2 && v.size() == 1) {
      m.corners.push_back(v[0]);
    } else if (kind[c] == 1 && v.size() == 2) {
      m.curves.push_back({v[0], v[1]});
    } else if (kind[c] == 0 && v.size() != 1 && !(has_polygons && v.size() == 2)) {
      if (lo[c] < 0 || lo[c] >= hi[c] || hi[c] > INT32_MAX)
        in.fail("cell " + std::to_string(c) + ": bad material pair");
      m.dim = v.size() == 4 ? 3 : 2;
      // 2D segments fill the unused ids with -1, as extract_model does.
      std::array<index_t, 4> f{v[0], v[1], v.size() == 4 ? v[2] : -1, v.size() == 4 ? v[3] : -1};
      m.facets.push_back(f);
      m.facet_materials.push_back({static_cast<int>(lo[c]), static_cast<int>(hi[c])});
    } else {
      in.fail("cell " + std::to_string(c) + ": kind " + std::to_string(kind[c]) +
              " does not fit its " + std::to_string(v.size()) + " points");
    }
  }
}

}  // namespace

ModelFile read_model_vtk(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw IoError(path + ": cannot open the model file");
  std::ostringstream buffer;
  buffer << file.rdbuf();
  if (file.bad()) throw IoError(path + ": read error");
  const std::string text = buffer.str();
  LegacyScanner in(text, path);
  ModelFile out;
  read_header(in, out);
  read_points(in, out.model);
  const Cells cells = read_cells(in, out.model.points.size());
  build(in, cells, out.model);
  return out;
}

}  // namespace hexadapt::reconstruct
