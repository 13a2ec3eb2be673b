// Private to the collection reader (vtk_collection.h): what its files share.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "../vtk_xml/vtk_xml_document.h"
#include "hexadapt/io/vtk_collection.h"

namespace hexadapt::io::detail {

/// What reading one collection needs: the options for the data sets (time selection already
/// applied), the loader and the nesting depth.
struct CollectionContext {
  ReadOptions options;
  FileLoader load;
  int depth = 0;
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

/// A .pvtu's pieces that rank `rank` of `size` reads (io::read_rank_pieces).
RankPieces read_rank_pieces(const VtkXmlDocument& doc, const CollectionContext& ctx, int rank,
                            int size);

/// Reads a parsed collection document (P* types, vtkMultiBlockDataSet, Collection).
MeshData read_collection_document(const VtkXmlDocument& doc, const CollectionContext& ctx);

/// Merges pieces of one mesh (see vtk_collection.h, .pvtu). `file` names the collection.
MeshData merge_pieces(std::vector<NamedMesh> pieces, double weld_tolerance,
                      const std::string& file);

/// The same, each rank holding some of the pieces: `index` gives each one's place in the
/// whole list (increasing, the ranks' in rank order). Every rank calls it; errors are the
/// same on every rank.
MeshPart merge_on_ranks(const dist::Communicator& comm, std::vector<NamedMesh> pieces,
                        const std::vector<std::int64_t>& index, double weld_tolerance,
                        const std::string& file);

/// The first piece of every rank's `pieces` (lowest rank first): its file, kind, metadata and
/// arrays without their values. Throws InputError naming `file` when no rank has a piece.
/// Every rank calls it.
NamedMesh first_piece_header(const dist::Communicator& comm, const std::vector<NamedMesh>& pieces,
                             const std::string& file);

/// Runs f on every rank; when it throws InputError on some, every rank throws the lowest such
/// rank's. Every rank calls it.
void agree_on_input_errors(const dist::Communicator& comm, const std::function<void()>& f);

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
