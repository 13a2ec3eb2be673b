// Private to the collection reader (vtk_collection.h): what its files share.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/io/vtk_collection.h"
#include "vtk_xml_document.h"

namespace hexadapt::io::detail {

/// What reading one collection needs: the options for the data sets (time selection already
/// applied), the loader and the nesting depth.
struct CollectionContext {
  ReadOptions options;
  FileLoader load;
  int depth = 0;
};

/// A piece or block of a collection, read, with its file name for messages.
struct NamedMesh {
  std::string file;
  MeshData data;
};

/// The path of `reference` (as the element `e` of `doc` gives it) relative to the folder of
/// doc.file. Throws InputError for an empty, absolute or escaping ("..") name.
std::string resolve_reference(const VtkXmlDocument& doc, const pugi::xml_node& e,
                              const std::string& reference);

/// Loads the file `path` (named by element `e` of `doc`). Throws IoError naming both.
std::string load_reference(const VtkXmlDocument& doc, const pugi::xml_node& e,
                           const std::string& path, const CollectionContext& ctx);

/// Reads any data set or collection file the element `e` of `doc` names by its attribute
/// `attribute`, dispatched on its content.
MeshData read_reference(const VtkXmlDocument& doc, const pugi::xml_node& e, const char* attribute,
                        const CollectionContext& ctx);

/// Reads a parsed collection document (P* types, vtkMultiBlockDataSet, Collection).
MeshData read_collection_document(const VtkXmlDocument& doc, const CollectionContext& ctx);

/// Merges pieces of one mesh (see vtk_collection.h, .pvtu). `file` names the collection.
MeshData merge_pieces(std::vector<NamedMesh> pieces, double weld_tolerance,
                      const std::string& file);

/// VTK's array of ghost flags (cell and point data of the pieces of a parallel file).
constexpr const char* ghost_array = "vtkGhostType";

/// True when the vtkGhostType cell array `ghost` (may be null) marks cell c as a duplicate:
/// a ghost cell that another piece owns.
bool is_ghost_cell(const DataArray* ghost, std::size_t c);

/// Removes the cells a vtkGhostType cell array marks as duplicates (another piece owns them)
/// and the vtkGhostType arrays; returns how many cells were removed.
index_t drop_ghost_cells(MeshData& data);

/// .pvts .pvtr .pvti: the pieces tiled into their WholeExtent, or into the window of
/// ctx.options.layers (the pieces outside it not read).
MeshData read_parallel_structured(const VtkXmlDocument& doc, const CollectionContext& ctx);

/// .pvts .pvtr .pvti: the shape of the grid, from the WholeExtent alone.
StructuredShape parallel_structured_shape(const VtkXmlDocument& doc);

/// .pvd: the DataSet elements of the time step the options choose.
std::vector<pugi::xml_node> select_time_step(const VtkXmlDocument& doc, const ReadOptions& options);

}  // namespace hexadapt::io::detail
