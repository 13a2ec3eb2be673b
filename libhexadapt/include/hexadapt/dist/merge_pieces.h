// The pieces of one unstructured mesh (a .pvtu's) merged into one mesh while spread over the
// ranks, each rank holding some of the pieces: points of different pieces within a tolerance
// become one point (the first in piece order), a cell that an earlier piece already gives is
// dropped, points no cell uses are dropped, and what stays is numbered in order. The result
// is the serial merge's (io/vtk_collection.h) for any number of ranks: the same rules on the
// same values, each decided by the one rank that sees every candidate.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {

/// The pieces one rank holds, concatenated: the global numbering of points and of cells is
/// every rank's in rank order (the pieces' order).
struct PiecesPart {
  int nodes_per_cell = 8;
  std::vector<Vec3> points;
  std::vector<double> tolerance;  ///< per point: how far another piece's point may be to weld
  std::vector<std::int64_t> point_piece;  ///< per point: its piece (an increasing index)
  std::vector<NodeId> cells;              ///< nodes_per_cell local point ids per cell
  std::vector<std::int64_t> cell_piece;   ///< per cell: its piece
};

/// What of the merged mesh one rank holds: its kept cells, in order, and their nodes.
struct MergedPart {
  std::vector<char> kept;                  ///< per input cell: not a repeat of an earlier piece's
  std::vector<NodeId> cells;               ///< kept cells' nodes, local node ids
  std::vector<std::int64_t> node_ids;      ///< per local node: its global id, increasing
  std::vector<std::int64_t> node_sources;  ///< per local node: the global input point it is
  std::int64_t cell_offset = 0;            ///< global id of the first kept cell
  std::int64_t n_cells = 0, n_nodes = 0;   ///< of the whole merged mesh
  std::int64_t welded = 0, repeated = 0;   ///< over every rank: points welded, cells dropped
};

/// Per point of `part`: 1 when its tolerance box meets the bounding box of another piece.
/// Only such points can weld, and only a cell all of whose points are such can repeat a cell
/// of another piece (a point welds only to a point within its tolerance). Every rank calls
/// it.
std::vector<char> near_other_pieces(const Communicator& comm, const PiecesPart& part);

/// For each point of `part`, the global id of the first point (in the global order) that it
/// is welded to: the first point of another piece within the tolerance of both (within
/// min(tolerance) of each other), followed while that one is welded to an earlier one; the
/// point itself when none. A point of tolerance 0 is never welded. Every rank calls it.
/// Points far from other pieces (`near`: near_other_pieces) are not sent anywhere.
std::vector<std::int64_t> weld(const Communicator& comm, const PiecesPart& part,
                               const std::vector<char>& near);

/// For each cell of `part` whose welded nodes (`welded`: weld's result) an earlier cell (global
/// order) of another piece has as a set, 1; 0 otherwise. Only cells whose points are all
/// `near` other pieces (near_other_pieces) are sent to be compared. Every rank calls it.
std::vector<char> repeated_cells(const Communicator& comm, const PiecesPart& part,
                                 const std::vector<std::int64_t>& welded,
                                 const std::vector<char>& near);

/// The merge of every rank's part (above). Every rank calls it.
MergedPart merge_pieces(const Communicator& comm, const PiecesPart& part);

}  // namespace hexadapt::dist
