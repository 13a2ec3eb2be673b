// The mesh adaptation pipelines (paper sec. 5, Fig. 10): from a grid with volume fractions
// and a per-cell material assignment to a conformal mesh whose cells each hold one material
// and whose interfaces follow the fractions.
//
// `base` (Fig. 10-a, Sculpt-like): targets, direct move of the interface nodes onto them,
// global pillowing of every material, global quality-preserving smoothing; no guarantee on
// the output quality (the comparison point of the paper's Table 1). `guaranteed` (Fig. 10-b:
// controlled move, then the move-smooth loop) reuses the same steps and keeps every cell at
// or above the threshold S_q, with its shortest edge at least min_edge times its local input
// size (size_criterion.h), when the input cells all are; an input cell failing either stops
// it (the result lists them in bad_input_cells and failures, sets stopped_bad_input and
// holds the input grid unchanged) unless allow_bad_input. A node that cannot reach its
// target slides onto its interface surface (controlled_move.h). Before the first controlled
// move (3D, by default: LayerStrategy) each material's interfaces are pillowed where every
// cell keeps both criteria (interface_pillow.h); between the first controlled move and the
// move-smooth loop (2D, by default), cavity pillowing (sec. 5.2, Alg. 5, cavity_pillow.h)
// gives the nodes left short new cells to move into; the last few nodes short of their
// targets get cavities at the end (late_cavity_share). Every node still short of its target
// then goes onto it where the nodes without a target around it can repair its cells
// (reach_surface.h). The nodes still farther than near_interface from their surface at the
// end are reported in `blocked`. In 3D, when asked and given the reconstruction's
// geometric model, the guaranteed method first corrects the targets (sec. 5.3,
// target_correction.h); otherwise the correction is skipped and the result says why. It is
// off by default. With the size criterion on, targets closer than it lets their grid edge
// be are then pushed apart along their interface (target_spacing.h). Frozen nodes
// (BoundaryOptions::frozen, guaranteed method) never move and get no layer or cavity around
// them (with pillow_frozen: their layers, the copies frozen too); resume_moves moves the
// nodes of an adapted mesh on once they are let go (what the parts adapted on the ranks of an
// MPI job do where they meet).
#pragma once

#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "hexadapt/adapt/cavity_pillow.h"
#include "hexadapt/adapt/controlled_move.h"
#include "hexadapt/adapt/global_pillow.h"
#include "hexadapt/adapt/interface_pillow.h"
#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/reach_surface.h"
#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/adapt/step_settings.h"
#include "hexadapt/adapt/target_correction.h"
#include "hexadapt/adapt/target_spacing.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/core/log.h"
#include "hexadapt/mesh/assigned_grid.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

enum class AdaptMethod { base, guaranteed };

/// Where the guaranteed method gives the interface nodes new cells to move into: `cavities`
/// pillowed around the nodes the first move left short (paper sec. 5.2), each material's
/// interfaces pillowed `first`, before the move (interface_pillow.h), or `both`. `automatic`:
/// cavities in 2D; in 3D a first layer, and when that leaves more than 1 - enough_share of
/// the interface nodes away from their interface, cavities too, keeping the result that
/// brings more nodes near their interface (the time is then that of both). In 2D, and on extruded
/// 2D cases, the move and the cavities reach the interfaces and a first layer cost reach (half the
/// nodes blocked on the extruded ones); on curved 3D surfaces the first layer reaches them where
/// cavities could not, and cavities after it gained almost nothing at three times the time
/// (docs/results.md).
enum class LayerStrategy { automatic, cavities, first, both };

/// "base" / "guaranteed"; throws OptionError for another name.
AdaptMethod parse_adapt_method(const std::string& name);
std::string to_string(AdaptMethod method);
/// "automatic" / "cavities" / "first" / "both"; throws OptionError for another name.
LayerStrategy parse_layer_strategy(const std::string& name);
std::string to_string(LayerStrategy strategy);

/// On the ranks of an MPI job, each adapting its part of a grid and the ghost layers around it:
/// how the guaranteed method takes its decisions together on every rank, so that the layers it
/// lays near the cuts between the parts are the same on every rank holding their cells. Empty
/// on one process. Every rank calls each at the same point of its run.
struct RankDecisions {
  /// Replaces `cells` (input cells, in this rank's ids, that a mending run left failing on
  /// this rank) with the cells this rank leaves out of the layers next: those of its cells
  /// that the run of any rank holding them left failing. True when some rank's run left a
  /// cell failing.
  std::function<bool(std::vector<CellId>& cells)> left_out;
  /// Replaces each value with its sum over the ranks.
  std::function<void(std::vector<double>& values)> add_up;
};

/// The threshold (S_q, the quality the guaranteed method keeps), pillow, smooth and boundary
/// settings are StepSettings', held once for every step.
struct AdaptOptions : StepSettings {
  AdaptMethod method = AdaptMethod::guaranteed;  ///< which pipeline runs
  /// Shortest edge / local input size every cell keeps (guaranteed); 0 = no size criterion.
  double min_edge = default_min_edge;
  /// guaranteed: the controlled move (its steps, drag and rounds).
  MoveOptions move;
  TargetOptions targets;               ///< target computation
  TargetCorrectionOptions correction;  ///< guaranteed, 3D: targets smoothed on the model
  /// guaranteed, with the size criterion: targets pushed apart where closer than it allows.
  TargetSpacingOptions spacing;
  Progress progress;  ///< phase progress, nullptr = silent
  /// guaranteed: run even when input cells are below the threshold (no guarantee then).
  bool allow_bad_input = false;
  int max_loops = 20;                               ///< guaranteed: move-smooth rounds at most
  LayerStrategy layers = LayerStrategy::automatic;  ///< guaranteed: cavities, first or both
  /// guaranteed, automatic, 3D: the share of interface nodes near their interface with a
  /// first layer beyond which cavities are not tried. Measured with the layers mended
  /// (mend_rounds): a first layer brings 97-100 % of them near on the 3D cases and 99.7-100 %
  /// on the extruded ones, and cavities never did better.
  double enough_share = 0.8;
  /// guaranteed: cavity pillowing (cavity_pillow.h): its starting vertex distance `range`,
  /// 0 = no cavities.
  CavityOptions cavity;
  /// guaranteed: the interfaces pillowed before the first move (interface_pillow.h): the
  /// attempts per material `rounds` (0 = none) and the `carve` around a failing cell;
  /// keep_failing is the mend runs'.
  InterfacePillowOptions interface_pillow;
  /// guaranteed, first layer: runs that keep the layers with their failing cells for the
  /// moves and a local smoothing to mend (interface_pillow.h), each one leaving the layers
  /// out around the cells the run before left failing; when none gets every cell passing,
  /// the layers are carved where they fail before the move. 0 = carve before the move only.
  int mend_rounds = 12;
  /// guaranteed: cavities are pillowed at the end around the nodes still short of their
  /// targets when they are at most this share of the interface nodes (0: never), and kept
  /// when a few more rounds of the loop then bring the nodes closer.
  double late_cavity_share = 0.01;
  /// guaranteed: the loop stops when a round lowers dist by no more than this share of it.
  double loop_tolerance = 1e-3;
  /// guaranteed, 3D: the loop's smoothing makes no Laplacian pull shorter than this many mean
  /// edge lengths around the node (its SmoothOptions::min_move; the other smoothings, and the
  /// loop in 2D, keep smooth.min_move). Every round moves the nodes again, so relaxing them to
  /// a hundredth of an edge first is work the next round undoes: 0.1 tries nodes a quarter
  /// as often, with as many interface nodes near their surface. In 2D the first round mostly
  /// ends the loop, and a 2D case left a node short with it (docs/benchmarks.md).
  double loop_min_move = 0.1;
  /// guaranteed: after the loop, the nodes still off their surface go onto it where their
  /// neighbours can repair the cells around them (reach_surface.h); passes = 0: no such step.
  ReachOptions reach;
  /// A node within this many local sizes (the mean local_size of its cells) of its interface
  /// surface has reached the interface; one farther is blocked.
  double near_interface = 0.05;
  /// guaranteed, on the ranks of an MPI job: the mending's left-out cells and the automatic
  /// layer choice decided by every rank together (their shares summed over the ranks' parts
  /// read, ghost cells included).
  RankDecisions ranks;
};

/// Why a node with a target did not reach it (the `blocked` point array).
enum class BlockReason : char {
  none = 0,
  quality = 1,  ///< a further step would put a cell around it below the threshold
  cavity = 2,   ///< and a cavity around it (for one of its materials) failed at every range
  frozen = 3,   ///< a frozen node (BoundaryOptions::frozen), held where it is
};

/// The cavities pillowed at the end of a run around the nodes still short of their targets
/// (AdaptOptions::late_cavity_share).
struct LateCavities {
  index_t short_nodes = 0;  ///< nodes with a target off it before them
  bool tried = false;       ///< short_nodes was within the share: cavities were tried
  index_t published = 0;    ///< cavities published
  bool kept = false;        ///< the rounds after them brought the nodes closer: in the output
};

/// One step of a pipeline, in the order it ran.
struct AdaptStep {
  std::string name;
  double min_quality = 1;  ///< smallest scaled Jacobian after the step
  index_t cells = 0;       ///< cells after the step
  double seconds = 0;
};

template <class M>
struct AdaptResult {
  M mesh;  ///< the output: one material per cell
  CellMaterials material;
  IdVector<NodeId, Vec3> target;  ///< each node's target (its own position when it has none)
  IdVector<NodeId, char> has_target;
  IdVector<NodeId, double> distance;  ///< |position - target|
  /// Distance to the interface surface through the target (surface_distance(); the target
  /// distance for the base method, whose nodes do not slide).
  IdVector<NodeId, double> surface_distance;
  IdVector<NodeId, char> near_interface;  ///< within near_interface local sizes of it
  /// guaranteed: where each node may move at the end (its boundary and interface directions;
  /// frozen nodes frozen): what resume_moves takes to move the nodes on.
  IdVector<NodeId, NodeConstraint> sliding;
  std::vector<AdaptStep> steps;
  index_t n_interface_nodes = 0;
  index_t n_reached = 0;           ///< interface nodes on their target at the end
  index_t n_near_interface = 0;    ///< interface nodes within near_interface of their surface
  double surface_dist_init = 0;    ///< sum of surface distances after the first move
  double surface_dist_final = 0;   ///< sum of surface distances at the end
  NodeId farthest;                 ///< the node with a target farthest from its surface
  double farthest_distance = 0;    ///< its surface distance
  double farthest_local_size = 0;  ///< the mean local size of its cells
  double dist_init = 0;            ///< sum of distances after the first (controlled or direct) move
  double dist_final = 0;           ///< sum of distances at the end
  double min_quality = 1;          ///< of the output
  index_t n_below_threshold = 0;   ///< output cells with scaled Jacobian < threshold
  index_t n_inverted = 0;          ///< output cells with scaled Jacobian <= 0
  index_t n_below_min_edge = 0;    ///< output cells breaking the size criterion
  /// Of the output: smallest shortest edge / local size over the cells.
  double min_edge_ratio = 0;
  IdVector<CellId, double> local_size;  ///< each output cell's local input size
  /// guaranteed: the input cell each output cell comes from (a layer cell: the cell it was
  /// inflated from).
  IdVector<CellId, CellId> cell_origin;
  IdVector<NodeId, NodeId> node_origin;  ///< guaranteed: the input node each node is (a copy of)
  /// The worst cells failing a criterion (at most 10): of the output, or of the input when
  /// the guaranteed method stopped on it.
  std::vector<CellFailure> failures;
  // Guaranteed method only.
  std::vector<CellId> bad_input_cells;  ///< input cells failing the threshold or min_edge
  bool stopped_bad_input = false;       ///< true: nothing was done (see bad_input_cells)
  double input_min_quality = 1;         ///< of the input grid
  IdVector<NodeId, char> blocked;       ///< BlockReason per node (all none for base)
  index_t n_blocked = 0;         ///< interface nodes farther than near_interface from their surface
  index_t n_frozen_blocked = 0;  ///< of those, frozen nodes (BlockReason::frozen)
  /// The worst cells next to blocked nodes, lowest quality first (at most 10).
  std::vector<std::pair<CellId, double>> blocking_cells;
  int loops = 0;                                   ///< move-smooth rounds run
  LayerStrategy layers = LayerStrategy::cavities;  ///< guaranteed: the strategy that ran
  /// automatic, 3D, when both strategies ran: interface nodes the one not kept brought near
  /// their interface.
  index_t other_near_interface = 0;
  std::vector<InterfacePillowAttempt> interface_pillows;  ///< per material, before the move
  /// Per run that kept the first layer's failing cells (AdaptOptions::mend_rounds): the input
  /// cells whose cells still failed at its end (the last 0: that run is the result).
  std::vector<index_t> mend_failing;
  index_t n_interface_layer_cells = 0;  ///< cells the interface pillowing added
  std::vector<CavityAttempt> cavities;  ///< every cavity tried, in order
  index_t n_cavities_published = 0;
  index_t n_cells_added = 0;          ///< layer cells of the published cavities
  TargetCorrectionResult correction;  ///< the 3D target correction (ran or why skipped)
  TargetSpacingResult spacing;        ///< the targets pushed apart for the size criterion
  ReachResult reach;                  ///< the nodes put on their surface after the loop
  LateCavities late_cavities;         ///< of the run that made the output
  /// The nodes short of their targets put on them (reach_targets) after the late cavities;
  /// ReachOptions::passes = 0: no such step.
  ReachResult late_reach;
};

/// Runs the chosen pipeline. `material` holds one index into `fractions`' materials per
/// cell; `model` is the reconstruction's geometric model of the same grid (nullptr: none,
/// the target correction is skipped); `targets`, guaranteed method only: the nodes' targets
/// as compute_targets gives them, e.g. on a larger grid around this one (a part of a grid
/// adapted on its own), instead of the ones of this grid (nullptr); the steps after it (the
/// frozen nodes, the correction, the spacing) run on them as usual. Throws InputError for
/// inconsistent sizes or a model whose material indices do not fit, OptionError for bad
/// options or targets of the wrong size.
template <class M>
AdaptResult<M> adapt(const M& grid, const Fractions& fractions, const CellMaterials& material,
                     const AdaptOptions& options = {},
                     const reconstruct::InterfaceModel* model = nullptr,
                     const Targets* targets = nullptr);

/// The result of either dimension.
using AnyAdaptResult = std::variant<AdaptResult<QuadMesh>, AdaptResult<HexMesh>>;

/// The same on an assigned grid (io::to_assigned_grid); InputError when it has no material.
AnyAdaptResult adapt(const AssignedGrid& grid, const AdaptOptions& options = {},
                     const reconstruct::InterfaceModel* model = nullptr,
                     const Targets* targets = nullptr);
/// The same on a grid given up: its points are moved into the frame the pipeline runs in
/// instead of copied there (a grid's worth of memory less); the grid is left unspecified.
AnyAdaptResult adapt(AssignedGrid&& grid, const AdaptOptions& options = {},
                     const reconstruct::InterfaceModel* model = nullptr,
                     const Targets* targets = nullptr);

/// What resume_moves did.
struct ResumeResult {
  int loops = 0;           ///< move-smooth rounds
  ReachResult reach;       ///< the nodes put on their surface
  ReachResult late_reach;  ///< the nodes put on their targets
};

/// Moves the nodes of a mesh the guaranteed method adapted on toward their targets, as its
/// last steps do: the move-smooth loop, the reach step and the loop again around what it moved,
/// then the nodes still short of their targets with their neighbours (no cell is added). A
/// cell passing the threshold and `size` keeps passing. For a mesh whose frozen nodes were
/// let go, e.g. where the parts adapted on ranks meet; `targets` gives each node's target (its
/// own position when it has none) and `sliding` where it may slide (AdaptResult::sliding);
/// the nodes `sliding` freezes stay where they are, whatever their targets.
template <class M>
ResumeResult resume_moves(M& mesh, const Targets& targets,
                          const IdVector<NodeId, NodeConstraint>& sliding,
                          const SizeCriterion& size, const AdaptOptions& options);

}  // namespace hexadapt
