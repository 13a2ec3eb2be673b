// UnstructuredGrid (.vtu): points, then cells from connectivity / offsets / types.
#include "../vtk_cells.h"
#include "hexadapt/core/error.h"
#include "vtk_xml_array.h"
#include "vtk_xml_reader.h"

namespace hexadapt::io::detail {

namespace {

pugi::xml_node named_array(const VtkXmlDocument& doc, const pugi::xml_node& cells,
                           const char* name) {
  for (const pugi::xml_node e : cells.children("DataArray"))
    if (std::string(e.attribute("Name").as_string()) == name) return e;
  throw InputError(doc.file, place(cells), std::string("no DataArray named '") + name + "'");
}

std::vector<Vec3> read_points(const VtkXmlDocument& doc, const pugi::xml_node& piece,
                              std::size_t n) {
  const pugi::xml_node points = piece.child("Points");
  if (!points) throw InputError(doc.file, place(piece), "no <Points> element");
  const pugi::xml_node e = points.child("DataArray");
  if (!e) throw InputError(doc.file, place(points), "no DataArray inside <Points>");
  const DataArray a = read_data_array(doc, e, n, 3);
  std::vector<Vec3> out(n);
  for (std::size_t k = 0; k < n; ++k)
    out[k] = Vec3(a.values[3 * k], a.values[3 * k + 1], a.values[3 * k + 2]);
  return out;
}

// Offsets are the end of each cell in the connectivity: non-decreasing from 0.
std::size_t check_offsets(const VtkXmlDocument& doc, const pugi::xml_node& e,
                          const std::vector<std::int64_t>& offsets) {
  std::int64_t previous = 0;
  for (std::size_t c = 0; c < offsets.size(); ++c) {
    if (offsets[c] < previous)
      throw InputError(doc.file, place(e) + ", cell " + std::to_string(c),
                       "offset " + std::to_string(offsets[c]) +
                           " is smaller than the previous "
                           "one (" +
                           std::to_string(previous) + ")");
    previous = offsets[c];
  }
  return static_cast<std::size_t>(previous);
}

}  // namespace

void read_unstructured(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data) {
  const pugi::xml_node dataset = doc.root.child("UnstructuredGrid");
  const pugi::xml_node piece = single_piece(doc, dataset);
  const std::uint64_t n_points = count_attribute(doc, piece, "NumberOfPoints");
  const std::uint64_t n_cells = count_attribute(doc, piece, "NumberOfCells");
  if (n_cells == 0 || n_points == 0)
    throw InputError(doc.file, place(piece),
                     "empty mesh: " + std::to_string(n_points) + " points and " +
                         std::to_string(n_cells) + " cells");
  if (n_points > static_cast<std::uint64_t>(std::numeric_limits<index_t>::max()) ||
      n_cells > static_cast<std::uint64_t>(std::numeric_limits<index_t>::max()))
    throw InputError(doc.file, place(piece), "too many points or cells for 32-bit ids");
  data.points = read_points(doc, piece, n_points);
  const pugi::xml_node cells = piece.child("Cells");
  if (!cells) throw InputError(doc.file, place(piece), "no <Cells> element");
  const pugi::xml_node offsets_e = named_array(doc, cells, "offsets");
  const std::vector<std::int64_t> offsets = read_int_array(doc, offsets_e, n_cells);
  const std::vector<std::int64_t> types =
      read_int_array(doc, named_array(doc, cells, "types"), n_cells);
  const std::size_t n_ids = check_offsets(doc, offsets_e, offsets);
  const std::vector<std::int64_t> ids =
      read_int_array(doc, named_array(doc, cells, "connectivity"), n_ids);
  data.cells.reserve(static_cast<std::size_t>(n_cells) * (n_ids > 4 * n_cells ? 8 : 4));
  std::size_t start = 0;
  for (std::size_t c = 0; c < n_cells; ++c) {
    const auto end = static_cast<std::size_t>(offsets[c]);
    if (types[c] < 0 || types[c] > 255)  // VTK cell types are bytes; keep int() from wrapping
      throw InputError(doc.file, "cell " + std::to_string(c),
                       "cell type " + std::to_string(types[c]) + " is not a VTK cell type");
    append_vtk_cell(data, static_cast<int>(types[c]), ids.data() + start, end - start,
                    static_cast<std::int64_t>(c), doc.file);
    start = end;
  }
  read_attributes(doc, dataset, piece, n_points, n_cells, data);
  finish_unstructured(data, options, doc.file);
}

}  // namespace hexadapt::io::detail
