// adapt on the ranks of a job, after ParMmg's iterative interface displacement. Each rank
// holds its part of the assigned grid (a structured grid's slab, or the cells PT-Scotch gave it
// of an unstructured mesh) and `adapt_ghost_layers` layers of ghost cells around it, and adapts
// them with the nodes its own cells share with other ranks' own cells (the cuts) frozen, the
// cells around them pillowed as one process pillows them (BoundaryOptions::pillow_frozen); its
// part of the mesh is the cells that come from its own cells. The ranks decide the mending
// together (RankDecisions), so the ranks holding a cut lay the same layers across it; where
// the copies of its nodes still do not meet, every rank adapts again with the cells around the
// cuts left unpillowed. Then the nodes around every cut move on, the ranks holding them moving
// the same band (docs/scaling.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/adapt/adapt_report.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/dist/block.h"

namespace hexadapt {

/// The layers of cells a rank holds beyond its own on each side: a node's target comes from
/// the faces around it, their cells' fraction gradients (fitted over the cells around those)
/// and the columns of three cells across a sheet; three layers hold all of them for the nodes
/// of the own layers, the cuts' too, and the cells whose layers cross a cut.
constexpr int adapt_ghost_layers = 3;

/// Where a rank's held cells sit in a structured grid cut in slabs across its last axis.
struct SlabPlace {
  dist::Slab slab;      ///< the rank's slab (dist::structured_slab), adapt_ghost_layers deep
  int grid_layers = 0;  ///< the whole grid's layers along the cut axis
};

/// How the layers lie across the cuts between the ranks' parts.
enum class CutLayers {
  pillowed,    ///< the cells around the cuts pillowed as one process pillows them
  unpillowed,  ///< left unpillowed (the ranks' layers did not meet)
  none,        ///< no layer holds a cut's node (2D: the layers are cavities)
};
std::string to_string(CutLayers layers);

/// The layers one rank's last run laid.
struct RankRun {
  LayerStrategy layers = LayerStrategy::cavities;
  std::vector<index_t> mend_failing;  ///< AdaptResult::mend_failing
  index_t interface_layer_cells = 0;
  index_t cavities_published = 0;
};

/// What a rank gets from adapt on ranks.
struct RankAdaptResult {
  /// This rank's part of the mesh: the cells that come from its own input cells. Node origins
  /// are in the ids of the cells held; the run's figures are `total`'s.
  AnyAdaptResult part;
  /// Some rank stopped on bad input cells (nothing adapted): `bad_input_cells` holds every
  /// rank's own ones by their ids in the whole grid, increasing.
  bool stopped_bad_input = false;
  std::vector<std::int64_t> bad_input_cells;
  /// The worst cells failing a criterion: of the output, by their ids in the gathered mesh
  /// (the parts in rank order); of the input when stopped, by their ids in the grid.
  std::vector<CellFailure> failures;
  AdaptFigures total;                ///< the run's
  std::vector<AdaptFigures> ranks;   ///< each rank's part's, in rank order
  std::vector<RankRun> runs;         ///< each rank's, in rank order
  CutLayers cut_layers = CutLayers::pillowed;
  /// For gathering the parts into one mesh (each node named by the one rank counting it): this
  /// part's nodes that a higher rank counts, each with its id past this rank's own points in
  /// the gathered mesh.
  std::vector<std::pair<index_t, index_t>> counted_above;
  PhaseTimes times;  ///< "adapt", then "cuts" (the second pass)
};

/// Adapts the cells this rank holds of the whole grid: `held`, its own cells and the
/// adapt_ghost_layers layers of ghost cells around them, `where.block` naming them (of a
/// slab, with `slab`; of an unstructured mesh cut in parts, a list whose own cells come first).
/// The guaranteed method only (OptionError otherwise); no model, so no target correction. An
/// error on some rank is thrown on every rank (dist::CommonError). Every rank calls it.
RankAdaptResult adapt(AssignedGrid&& held, const AdaptOptions& options,
                      const dist::Distribution& where,
                      const std::optional<SlabPlace>& slab = std::nullopt);

/// The figures of each rank and the layers of its runs as the report's `ranks` fields, and how
/// the layers lie across the cuts: a JSON object.
std::string rank_adapt_json(const RankAdaptResult& r);

}  // namespace hexadapt
