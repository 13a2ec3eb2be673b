// The plain text formats of hand-made cases (DESIGN sec. 7.1). The structured format is told
// from the unstructured one by its second line: "ni nj [nk]" against a single node count.
#include "hexadapt/io/text_case.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/legacy_scanner.h"
#include "vtk_cells.h"

namespace hexadapt::io {

namespace {

// Number of tokens on the first non-blank line after the current position (not consumed).
std::size_t tokens_on_next_line(LegacyScanner& s) {
  LegacyScanner look = s;
  look.at_end();  // skips the newline and any blank lines
  const std::string_view l = look.line();
  std::size_t n = 0;
  for (std::size_t k = 0; k < l.size();) {
    while (k < l.size() && (l[k] == ' ' || l[k] == '\t' || l[k] == '\r')) ++k;
    if (k < l.size()) ++n;
    while (k < l.size() && l[k] != ' ' && l[k] != '\t' && l[k] != '\r') ++k;
  }
  return n;
}

// Maps a file's cell number to MeshData's: the 2D format numbers cells j fastest.
struct CellNumbering {
  std::int64_t n_cells = 0;
  std::int64_t ni = 0, nj = 0;  ///< > 0 for the 2D structured format only
  std::int64_t operator()(std::int64_t c) const { return nj > 0 ? (c / nj) + ni * (c % nj) : c; }
};

void read_structured_mesh(LegacyScanner& s, int dim, MeshData& data, CellNumbering& numbering) {
  std::array<std::int64_t, 3> dims{2, 2, 1};
  std::int64_t n_points = 1;
  for (int a = 0; a < dim; ++a) {
    const auto n = s.integer("a number of cells per axis", 1, max_legacy_id - 1);
    dims[static_cast<std::size_t>(a)] = n + 1;
    n_points *= n + 1;
    if (n_points > max_legacy_id) s.fail("too many cells for 32-bit ids");
  }
  // Refuse millions of cells announced in a file too small to list fractions for them,
  // before allocating the lattice.
  if (n_points > (1 << 20) && static_cast<std::size_t>(n_points / 8) > s.remaining())
    s.fail("the grid has " + std::to_string(n_points) + " nodes but only " +
           std::to_string(s.remaining()) + " bytes follow");
  std::vector<Vec3> pts;
  pts.reserve(static_cast<std::size_t>(n_points));
  for (std::int64_t k = 0; k < dims[2]; ++k)
    for (std::int64_t j = 0; j < dims[1]; ++j)
      for (std::int64_t i = 0; i < dims[0]; ++i)
        pts.emplace_back(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k));
  detail::fill_structured(data, dims, std::move(pts), ReadOptions{}, s.file());
  numbering.n_cells = data.n_cells();
  if (dim == 2) numbering.ni = dims[0] - 1, numbering.nj = dims[1] - 1;
}

void read_unstructured_mesh(LegacyScanner& s, MeshData& data, CellNumbering& numbering) {
  const auto n_nodes = s.integer("a number of nodes", 0, max_legacy_id);
  static constexpr LegacyType kDouble{"double", ScalarType::float64, 8, true};
  const auto xyz = s.reals(kDouble, 3 * static_cast<std::size_t>(n_nodes), "node coordinates");
  for (std::size_t p = 0; p < static_cast<std::size_t>(n_nodes); ++p)
    data.points.emplace_back(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);
  const auto n_cells = s.integer("a number of cells", 0, max_legacy_id);
  for (std::int64_t c = 0; c < n_cells; ++c) {
    const std::size_t at = s.mark();
    const auto n = s.integer("a number of cell nodes", 0, max_legacy_id);
    if (n != 4)
      s.fail_at(at, "cell " + std::to_string(c) + " has " + std::to_string(n) +
                        " nodes, expected 4 (quads)");
    std::array<std::int64_t, 4> ids{};
    for (auto& id : ids) id = s.integer("a node index", 0, n_nodes - 1);
    detail::append_vtk_cell(data, detail::vtk_quad, ids.data(), 4, c, s.file());
  }
  detail::finish_unstructured(data, ReadOptions{}, s.file());
  numbering.n_cells = data.n_cells();
}

// The materials read so far, in the order they first appear, with the cells listed for them.
struct Listed {
  std::vector<DataArray> arrays;
  std::vector<std::vector<bool>> seen;
};

// The material indices and names of the block being read.
struct BlockMaterials {
  std::vector<std::int64_t> indices;
  std::vector<std::string> names;
};

// One material of a block: a new one, or the one of that name from an earlier block, which
// the block lists more cells for (as the reference implementation reads blocks: materials
// are known by name, their indices only number them within the block).
void read_material(LegacyScanner& s, const CellNumbering& numbering, BlockMaterials& block,
                   Listed& listed) {
  const std::size_t at = s.mark();
  const auto index = s.integer("a material index", 0, max_legacy_id);
  if (std::find(block.indices.begin(), block.indices.end(), index) != block.indices.end())
    s.fail_at(at, "material index " + std::to_string(index) + " listed twice");
  block.indices.push_back(index);
  const std::string name = "vf_" + std::string(s.expect_token("a material name"));
  if (std::find(block.names.begin(), block.names.end(), name) != block.names.end())
    s.fail_at(at, "material " + quote_token(name.substr(3)) + " listed twice");
  block.names.push_back(name);
  const auto found = std::find_if(listed.arrays.begin(), listed.arrays.end(),
                                  [&](const DataArray& a) { return a.name == name; });
  const auto m = static_cast<std::size_t>(found - listed.arrays.begin());
  if (m == listed.arrays.size()) {
    listed.arrays.emplace_back().name = name;
    listed.arrays.back().values.assign(static_cast<std::size_t>(numbering.n_cells), 0.0);
    listed.seen.emplace_back(static_cast<std::size_t>(numbering.n_cells), false);
  }
  const auto n = s.integer("a number of listed cells", 0, numbering.n_cells);
  for (std::int64_t e = 0; e < n; ++e) {
    const auto written = s.integer("a cell index", 0, numbering.n_cells - 1);
    const auto c = static_cast<std::size_t>(numbering(written));
    // Values and sums are judged with the others', by the fraction options and their
    // tolerances (fractions.h); here only what is not a fraction at all.
    const double f = s.real("a volume fraction");
    if (!std::isfinite(f)) s.fail("volume fraction " + std::to_string(f) + " is not a number");
    if (listed.seen[m][c])
      s.fail("cell " + std::to_string(written) + " listed twice for material " +
             quote_token(name.substr(3)));
    listed.seen[m][c] = true;
    listed.arrays[m].values[c] = f;
  }
}

// A block: its number of materials, then each material.
void read_block(LegacyScanner& s, const CellNumbering& numbering, Listed& listed) {
  const auto n_mat = s.integer("the number of materials", 1, 1 << 16);
  BlockMaterials block;
  for (std::int64_t m = 0; m < n_mat; ++m) read_material(s, numbering, block, listed);
}

}  // namespace

MeshData read_text_case(std::string_view content, const std::string& file) {
  LegacyScanner s(content, file);
  MeshData data;
  CellNumbering numbering;
  const auto dim = static_cast<int>(s.integer("the dimension (2 or 3)", 2, 3));
  const std::size_t on_line_2 = tokens_on_next_line(s);
  std::int64_t blocks = 1;  // the unstructured format has one, uncounted
  if (on_line_2 == static_cast<std::size_t>(dim)) {
    read_structured_mesh(s, dim, data, numbering);
    blocks = s.integer("the number of blocks", 1, 1 << 16);
  } else if (on_line_2 == 1 && dim == 2) {
    read_unstructured_mesh(s, data, numbering);
  } else {
    s.fail("expected " + std::to_string(dim) + " cell counts (structured format)" +
           (dim == 2 ? " or a node count (unstructured format)" : "") + " on the second line");
  }
  Listed listed;
  for (std::int64_t b = 0; b < blocks; ++b) read_block(s, numbering, listed);
  for (DataArray& a : listed.arrays) data.set_cell_array(std::move(a));
  if (!s.at_end()) s.fail("unexpected " + quote_token(s.peek_token()) + " after the last material");
  return data;
}

}  // namespace hexadapt::io
