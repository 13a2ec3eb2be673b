// The collection reader: which files a .pvtu, .vtm or .pvd names, read one by one and
// handed to the merge (vtk_collection_merge.cpp), the structured tiling
// (vtk_collection_structured.cpp) or the time-step choice (vtk_collection_time.cpp).
#include "vtk_collection.h"

#include <iterator>
#include <limits>

#include "../vtk_xml/vtk_xml_reader.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"

namespace hexadapt::io {

namespace detail {

namespace {

// A .pvd of .pvtu files of pieces: two levels; more than 4 is a file naming itself.
constexpr int max_depth = 4;

std::string folder_of(const std::string& file) {
  const std::size_t slash = file.find_last_of('/');
  return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

bool has_parent_component(const std::string& path) {
  std::size_t start = 0;
  while (start <= path.size()) {
    std::size_t end = path.find_first_of("/\\", start);
    if (end == std::string::npos) end = path.size();
    if (path.compare(start, end - start, "..") == 0) return true;
    start = end + 1;
  }
  return false;
}

pugi::xml_node parallel_unstructured(const VtkXmlDocument& doc) {
  const pugi::xml_node dataset = doc.root.child("PUnstructuredGrid");
  if (!dataset) throw InputError(doc.file, place(doc.root), "no <PUnstructuredGrid> element");
  return dataset;
}

// The pieces [first, end) of a .pvtu's list read into `pieces`, their places in the list into
// `index`; empty pieces (VTK writes them when there are more pieces than cells) are skipped.
void read_pieces(const VtkXmlDocument& doc, const CollectionContext& ctx, std::size_t first,
                 std::size_t end, std::vector<NamedMesh>& pieces,
                 std::vector<std::int64_t>& index) {
  std::size_t k = 0;
  for (const pugi::xml_node e : parallel_unstructured(doc).children("Piece")) {
    if (k++ < first) continue;
    if (k > end) break;
    const std::string path = resolve_reference(doc, e, e.attribute("Source").as_string());
    const std::string content = load_reference(doc, e, path, ctx);
    VtkXmlDocument piece;
    load_vtk_xml(piece, content, path);
    if (piece.type != "UnstructuredGrid")
      throw InputError(doc.file, place(e),
                       "piece " + quote_token(path) + " is a " + quote_token(piece.type) +
                           ", expected an UnstructuredGrid as the .pvtu announces");
    const pugi::xml_node p = piece.root.child("UnstructuredGrid").child("Piece");
    if (p && count_attribute(piece, p, "NumberOfCells") == 0) continue;
    NamedMesh m{path, {}};
    read_unstructured(piece, ctx.options, m.data);
    pieces.push_back(std::move(m));
    index.push_back(static_cast<std::int64_t>(k - 1));
  }
}

MeshData read_parallel_unstructured(const VtkXmlDocument& doc, const CollectionContext& ctx) {
  std::vector<NamedMesh> pieces;
  std::vector<std::int64_t> index;
  read_pieces(doc, ctx, 0, std::numeric_limits<std::size_t>::max(), pieces, index);
  if (pieces.empty())
    throw InputError(doc.file, place(parallel_unstructured(doc)), "no piece with cells");
  return merge_pieces(std::move(pieces), ctx.options.weld_tolerance, doc.file);
}

// Every DataSet with a file attribute under a .vtm's blocks and pieces, in document order.
void collect_datasets(const pugi::xml_node& parent, std::vector<pugi::xml_node>& out) {
  for (const pugi::xml_node e : parent.children()) {
    if (std::string(e.name()) == "DataSet") {
      if (e.attribute("file")) out.push_back(e);
    } else {
      collect_datasets(e, out);
    }
  }
}

MeshData read_datasets(const VtkXmlDocument& doc, const std::vector<pugi::xml_node>& datasets,
                       const pugi::xml_node& parent, const CollectionContext& ctx) {
  if (datasets.empty())
    throw InputError(doc.file, place(parent), "no DataSet element names a file: nothing to read");
  std::vector<NamedMesh> parts;
  for (const pugi::xml_node e : datasets) {
    NamedMesh m{resolve_reference(doc, e, e.attribute("file").as_string()), {}};
    m.data = read_reference(doc, e, "file", ctx);
    parts.push_back(std::move(m));
  }
  if (parts.size() == 1) return std::move(parts.front().data);
  return merge_pieces(std::move(parts), ctx.options.weld_tolerance, doc.file);
}

MeshData read_multiblock(const VtkXmlDocument& doc, const CollectionContext& ctx) {
  const pugi::xml_node dataset = doc.root.child(doc.type.c_str());
  if (!dataset)
    throw InputError(doc.file, place(doc.root), "no <" + doc.type + "> element inside <VTKFile>");
  std::vector<pugi::xml_node> datasets;
  collect_datasets(dataset, datasets);
  return read_datasets(doc, datasets, dataset, ctx);
}

MeshData read_time_series(const VtkXmlDocument& doc, const CollectionContext& ctx) {
  const std::vector<pugi::xml_node> datasets = select_time_step(doc, ctx.options);
  CollectionContext inner = ctx;
  inner.options.step.reset();
  inner.options.time.reset();
  return read_datasets(doc, datasets, doc.root.child("Collection"), inner);
}

bool is_collection_type(const std::string& t) {
  return t == "PUnstructuredGrid" || t == "PStructuredGrid" || t == "PRectilinearGrid" ||
         t == "PImageData" || t == "vtkMultiBlockDataSet" || t == "vtkMultiPieceDataSet";
}

}  // namespace

std::string resolve_reference(const VtkXmlDocument& doc, const pugi::xml_node& e,
                              const std::string& reference) {
  if (reference.empty()) throw InputError(doc.file, place(e), "no file name");
  if (reference.front() == '/' || has_parent_component(reference))
    throw InputError(doc.file, place(e),
                     "file " + quote_token(reference) +
                         ": only names relative to the folder of this file, without '..', are "
                         "read (move or link the files under that folder)");
  return folder_of(doc.file) + reference;
}

std::string load_reference(const VtkXmlDocument& doc, const pugi::xml_node& e,
                           const std::string& path, const CollectionContext& ctx) {
  try {
    return ctx.load(path);
  } catch (const IoError& error) {
    throw IoError(doc.file + ": " + place(e) + ": cannot read the file it names: " + error.what());
  }
}

MeshData read_reference(const VtkXmlDocument& doc, const pugi::xml_node& e, const char* attribute,
                        const CollectionContext& ctx) {
  const std::string path = resolve_reference(doc, e, e.attribute(attribute).as_string());
  if (ctx.depth >= max_depth)
    throw InputError(doc.file, place(e),
                     "collections nested more than " + std::to_string(max_depth) +
                         " deep (a file that names itself?)");
  const std::string content = load_reference(doc, e, path, ctx);
  VtkXmlDocument inner;
  load_vtk_xml(inner, content, path);
  const std::string& t = inner.type;
  MeshData data;
  if (t == "UnstructuredGrid") {
    read_unstructured(inner, ctx.options, data);
  } else if (t == "ImageData" || t == "RectilinearGrid" || t == "StructuredGrid") {
    read_structured(inner, ctx.options, data);
  } else if (t == "Collection") {
    throw InputError(doc.file, place(e),
                     quote_token(path) +
                         " is a time series inside a "
                         "collection: not read");
  } else if (is_collection_type(t)) {
    CollectionContext nested = ctx;
    ++nested.depth;
    data = read_collection_document(inner, nested);
  } else {
    throw InputError(doc.file, place(e),
                     quote_token(path) + " holds a " + quote_token(t) +
                         ": not a grid of quads or hexes (UnstructuredGrid, ImageData, "
                         "RectilinearGrid, StructuredGrid or a collection of them)");
  }
  return data;
}

MeshData read_collection_document(const VtkXmlDocument& doc, const CollectionContext& ctx) {
  const std::string& t = doc.type;
  if (t == "PUnstructuredGrid") return read_parallel_unstructured(doc, ctx);
  if (t == "PStructuredGrid" || t == "PRectilinearGrid" || t == "PImageData")
    return read_parallel_structured(doc, ctx);
  if (t == "vtkMultiBlockDataSet" || t == "vtkMultiPieceDataSet") return read_multiblock(doc, ctx);
  if (t == "Collection") return read_time_series(doc, ctx);
  throw InputError(doc.file, place(doc.root),
                   "type " + quote_token(t) +
                       " is not a collection (PUnstructuredGrid, PStructuredGrid, "
                       "PRectilinearGrid, PImageData, vtkMultiBlockDataSet or Collection)");
}

RankPieces read_rank_pieces(const VtkXmlDocument& doc, const CollectionContext& ctx, int rank,
                            int size) {
  const std::size_t n =
      static_cast<std::size_t>(std::distance(parallel_unstructured(doc).children("Piece").begin(),
                                             parallel_unstructured(doc).children("Piece").end()));
  const auto share = [&](int r) {
    return n * static_cast<std::size_t>(r) / static_cast<std::size_t>(size);
  };
  RankPieces out;
  out.file = doc.file;
  read_pieces(doc, ctx, share(rank), share(rank + 1), out.pieces, out.index);
  return out;
}

}  // namespace detail

MeshData read_vtk_collection(std::string_view content, const std::string& file,
                             const ReadOptions& options, const FileLoader& load) {
  detail::VtkXmlDocument doc;
  detail::load_vtk_xml(doc, content, file);
  detail::CollectionContext ctx{options, load, 0};
  return detail::read_collection_document(doc, ctx);
}

}  // namespace hexadapt::io
