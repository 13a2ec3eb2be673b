#include "vtk_xml_reader.h"

#include "../provenance.h"
#include "../vtk_xml_comment.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/log.h"
#include "hexadapt/io/vtk_xml.h"
#include "vtk_xml_array.h"

namespace hexadapt::io {

namespace detail {

pugi::xml_node single_piece(const VtkXmlDocument& doc, const pugi::xml_node& dataset) {
  if (!dataset)
    throw InputError(doc.file, place(doc.root), "no <" + doc.type + "> element inside <VTKFile>");
  const pugi::xml_node piece = dataset.child("Piece");
  if (!piece) throw InputError(doc.file, place(dataset), "no <Piece>: the data set is empty");
  if (piece.next_sibling("Piece"))
    throw InputError(doc.file, place(piece.next_sibling("Piece")),
                     "several <Piece> elements: multi-piece files are not supported (merge "
                     "them first, e.g. with ParaView's Merge Blocks)");
  return piece;
}

namespace {

void read_arrays(const VtkXmlDocument& doc, const pugi::xml_node& group, std::size_t n_tuples,
                 std::vector<DataArray>& out) {
  int k = 0;
  for (const pugi::xml_node e : group.children("DataArray")) {
    if (std::string(e.attribute("type").as_string()) == "String") {
      log_warning(doc.file + ": " + place(e) + ": string arrays in point or cell data are skipped");
      continue;
    }
    DataArray a = read_data_array(doc, e, n_tuples);
    if (a.name.empty()) a.name = "unnamed_" + std::to_string(k);
    ++k;
    for (const DataArray& old : out)
      if (old.name == a.name)
        throw InputError(doc.file, place(e), "two arrays named " + quote_token(a.name));
    out.push_back(std::move(a));
  }
}

// String arrays become metadata entries. Our own `hexadapt_command` repeats the last command
// of the metadata comment: it is taken only from a file that lost the comment (saved again by
// ParaView, which keeps field data).
void read_field_data(const VtkXmlDocument& doc, const pugi::xml_node& field, bool have_comment,
                     MeshData& data) {
  for (const pugi::xml_node e : field.children("DataArray")) {
    if (std::string(e.attribute("type").as_string()) != "String") continue;
    if (have_comment && std::string(e.attribute("Name").as_string()) == command_key) continue;
    const std::vector<std::string> values = read_string_array(doc, e);
    std::string joined;
    for (std::size_t k = 0; k < values.size(); ++k) joined += (k ? "\n" : "") + values[k];
    data.metadata.emplace_back(e.attribute("Name").as_string(), joined);
  }
}

// Our metadata comment, before <VTKFile> or among its children (the first one found).
// Returns whether there was one.
bool read_metadata_comment(const VtkXmlDocument& doc, MeshData& data) {
  for (const pugi::xml_node parent : {doc.xml.root(), doc.root})
    for (const pugi::xml_node c : parent.children())
      if (c.type() == pugi::node_comment)
        if (auto entries = parse_metadata_comment(c.value())) {
          for (auto& entry : *entries) data.metadata.push_back(std::move(entry));
          return true;
        }
  return false;
}

}  // namespace

void read_attributes(const VtkXmlDocument& doc, const pugi::xml_node& dataset,
                     const pugi::xml_node& piece, std::size_t n_points, std::size_t n_cells,
                     MeshData& data) {
  read_arrays(doc, piece.child("PointData"), n_points, data.point_data);
  read_arrays(doc, piece.child("CellData"), n_cells, data.cell_data);
  const bool have_comment = read_metadata_comment(doc, data);
  read_field_data(doc, dataset.child("FieldData"), have_comment, data);
}

}  // namespace detail

MeshData read_vtk_xml(std::string_view content, const std::string& file,
                      const ReadOptions& options) {
  detail::VtkXmlDocument doc;
  detail::load_vtk_xml(doc, content, file);
  MeshData data;
  if (doc.type == "UnstructuredGrid")
    detail::read_unstructured(doc, options, data);
  else if (doc.type == "ImageData" || doc.type == "RectilinearGrid" || doc.type == "StructuredGrid")
    detail::read_structured(doc, options, data);
  else
    throw InputError(file, detail::place(doc.root),
                     "data set type " + quote_token(doc.type) +
                         " is not supported (expected UnstructuredGrid, "
                         "ImageData, RectilinearGrid or StructuredGrid)");
  return data;
}

}  // namespace hexadapt::io
