// VTK files that refer to other files: parallel data sets (.pvtu .pvts .pvtr .pvti: one
// piece per file), multi-block data sets (.vtm) and time series (.pvd), read as one mesh
// (DESIGN sec. 2, the inputs parallel Eulerian codes and ParaView write).
//
// - .pvtu: the pieces are merged; ghost cells (vtkGhostType with the duplicate bit) are
//   dropped, points of different pieces closer than ReadOptions::weld_tolerance times the
//   shortest cell edge at them are one point (the first in piece order), a cell given by two
//   pieces is kept once, points no cell uses are dropped. Numbering: the pieces' cells and
//   points in the order the file lists the pieces, so the same files give the same mesh.
// - .pvts .pvtr .pvti: the pieces must tile the WholeExtent (overlaps allowed); the result is
//   that one structured grid, as if read from a single file.
// - .vtm: every block that names a file (nested blocks and multi-piece blocks included), of
//   any data set type read here, merged as the pieces of a .pvtu; all blocks must hold the
//   same kind of cell (quads or hexes). A single block is read as it is.
// - .pvd: the data sets of one time step (several parts are merged as blocks), chosen by
//   ReadOptions::step (0-based, in increasing time) or ::time (within 1e-6 relative); a
//   series of several steps needs one of them, and an unknown one is an error listing the
//   steps and their times. Files without time steps ignore step and time.
// Referenced files are read relative to the folder of the file that names them; absolute
// names and names with a ".." component are refused, so a collection is a self-contained
// folder tree and cannot make the reader open files elsewhere. Collections may nest (a .pvd
// of .pvtu files) up to 4 levels.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "hexadapt/dist/communicator.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/mesh_part.h"

namespace hexadapt::io {

/// Returns the bytes of a file a collection refers to (its path resolved as described
/// above). Throws IoError when it cannot be read.
using FileLoader = std::function<std::string(const std::string& path)>;

/// Reads a collection file held in memory; `file` is its path (it locates the referenced
/// files and names the file in errors). Throws InputError (malformed, lying or inconsistent
/// content, a missing or unknown step, naming the file and element), IoError (a referenced
/// file cannot be read, naming it).
MeshData read_vtk_collection(std::string_view content, const std::string& file,
                             const ReadOptions& options, const FileLoader& load);

/// A piece or block of a collection, read, with its file name for messages.
struct NamedMesh {
  std::string file;
  MeshData data;
};

/// The pieces of a .pvtu one rank of `size` reads: a contiguous share of the pieces the file
/// lists (rank r: pieces [r P / size, (r + 1) P / size) of P), empty pieces left out.
struct RankPieces {
  std::string file;  ///< the .pvtu
  std::vector<NamedMesh> pieces;
  std::vector<std::int64_t> index;  ///< each piece's place in the file's list
};

/// Reads rank `rank`'s pieces of the .pvtu `path` (RankPieces). Throws OptionError for
/// another file type, InputError and IoError as read_mesh does.
RankPieces read_rank_pieces(const std::string& path, const ReadOptions& options, int rank,
                            int size);

/// Merges every rank's pieces as read_mesh merges a .pvtu's (above): the merged mesh is the
/// one read_mesh gives, whatever the number of ranks, each rank holding a contiguous range
/// of its cells (the cells of its pieces that stay), every rank's in rank order. Every rank calls
/// it; errors (InputError: pieces of another kind of cell or other arrays than the first; no piece
/// with cells) are the same on every rank.
MeshPart merge_rank_pieces(const dist::Communicator& comm, RankPieces pieces,
                           const ReadOptions& options);

}  // namespace hexadapt::io
