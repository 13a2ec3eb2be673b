// A stage's grid and its output on the ranks a computation is spread over: each rank reads its
// slab of a structured grid (dist/block.h), or holds its part of an unstructured mesh cut by
// the communicator's partitioner (PT-Scotch over MPI), with ghost layers, and writes the cells
// it owns as one piece of a .pvtu, or sends them to rank 0, which writes one file of the whole
// grid. Errors are common to every rank (dist::on_every_rank: dist::CommonError).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hexadapt/dist/block.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/mesh_part.h"
#include "hexadapt/io/vtk_collection.h"

namespace hexadapt::io {

/// What one rank reads of the input grid.
struct RankInput {
  bool structured = true;        ///< a structured grid's slab, or a part of an unstructured mesh
  StructuredShape shape;         ///< the whole grid's (of an unstructured mesh: its dim only)
  dist::Slab slab;               ///< the part this rank holds, and owns (unstructured: the block,
                                 ///< a list, only)
  MeshData data;                 ///< the held layers, or cells
  std::int64_t whole_cells = 0;  ///< of the whole grid or mesh
};

/// Every rank's slab of the structured grid in `path`, holding `ghost_layers` layers of
/// cells beyond the ones it owns; cut by layer counts, or by `layer_weights` (one per layer
/// across the cut axis: dist::weighted_slab) when given. A parallel file's pieces outside a
/// slab are not read by its rank; a single file is read whole by every rank, then cut.
/// An unstructured mesh's file (.pvtu .vtu .exo .e .g) is an OptionError (this stage reads
/// structured grids only on ranks).
RankInput read_on_ranks(const dist::Communicator& comm, const std::string& path,
                        ReadOptions options, int ghost_layers,
                        const std::vector<double>& layer_weights = {});

/// Every rank's share of the pieces of the unstructured mesh in `path` (RankPieces): of a
/// .pvtu, the pieces read_rank_pieces gives it; a single file (.vtu .exo .e .g) is read
/// by rank 0, as one piece. Another file is an OptionError. Errors are common to every rank.
RankPieces read_pieces_on_ranks(const dist::Communicator& comm, const std::string& path,
                                const ReadOptions& options);

/// The weight of each cell of a part of an unstructured mesh (one value > 0 per cell of the
/// part, e.g. the bytes a stage needs for it), for the cut to balance.
using CellWeights = std::function<std::vector<double>(const MeshPart&)>;

/// read_on_ranks' slab of a structured grid, or every rank's part of the unstructured mesh in
/// `path` (.pvtu .vtu .exo .e .g) with `ghost_layers` layers of ghost cells: a .pvtu's pieces
/// are read by the ranks in turn (a single file by rank 0) and merged as one process merges
/// them (merge_rank_pieces: the ids of one process's mesh), then the cells are cut into
/// one part per rank by Communicator::parts_of on their dual graph, each part's ghosts the cells
/// within `ghost_layers` rings of node neighbours (with_ghost_layers). With `cell_weights`, the
/// parts balance the cells' weights (each over the lightest cell's, rounded, 1 to 64) instead
/// of their counts; `layer_weights` are a grid's (read_on_ranks). Errors are common to every
/// rank.
RankInput read_mesh_on_ranks(const dist::Communicator& comm, const std::string& path,
                             const ReadOptions& options, int ghost_layers,
                             const std::vector<double>& layer_weights = {},
                             const CellWeights& cell_weights = {});

/// Writes the owned part of every rank's `held` data (the layers of `input.slab`, or the
/// owned cells of an unstructured part and the nodes they use) to `path`:
/// a .pvtu naming one .vtu piece per rank (`<path without .pvtu>_<rank>.vtu`, written by
/// their ranks), or with `gather` one file of the whole grid in any format, written by
/// rank 0 with the same bytes a run on one process writes. Rank 0 holds the whole mesh twice
/// while gathering: beyond `memory_limit` (when > 0) every rank stops (ResourceError) before
/// anything travels. Errors are common to every rank.
void write_on_ranks(const dist::Communicator& comm, MeshData held, const RankInput& input,
                    const std::string& path, bool gather, const WriteOptions& options,
                    double memory_limit);

/// Makes `piece` fit write_disjoint_pieces' gathering when some of its nodes are the next
/// rank's piece's too (a slab's top cut, which the rank above owns): `shared` pairs each such
/// node with its id in the next piece. Drops them, and its cells name them by the ids past its
/// own points that those nodes take in the gathered mesh.
void drop_next_piece_nodes(MeshData& piece, const std::vector<std::pair<index_t, index_t>>& shared);

/// Writes every rank's `piece`, the part of one unstructured mesh whose cells the rank owns (no
/// point shared with another piece but as drop_next_piece_nodes leaves them, the whole being
/// the pieces in rank order), to `path`: a
/// .pvtu naming one .vtu per rank that has cells, or with `gather` one file written by
/// rank 0 with the bytes of one process writing the whole mesh (checked against
/// `memory_limit` as write_on_ranks does). With `order_by` (the name of a cell array, e.g.
/// the input cell each output cell comes from), the gathered cells are put in the increasing
/// order of its values, and the points in the order of the cells using them, both stably:
/// the order of one process when each rank's piece is in that order and no point is used
/// by cells of two values. Errors are common to every rank.
void write_disjoint_pieces(const dist::Communicator& comm, const MeshData& piece,
                           const std::string& path, bool gather, const WriteOptions& options,
                           double memory_limit, const std::string& order_by = {});

}  // namespace hexadapt::io
