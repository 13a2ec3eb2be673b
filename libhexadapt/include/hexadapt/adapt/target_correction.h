// Target correction (paper sec. 5.3, Fig. 18): in 3D the targets of the interface nodes
// span a surface, the "target surface" (the faces between cells of different materials,
// with their nodes placed at their targets), whose quads can be very poor (Fig. 18-a: 0.068)
// and then stop the controlled move early. The correction smooths that surface while keeping
// every target on the geometric model of the reconstruction (Fig. 18-b, c), so that the
// targets stay where the volume fractions put the interfaces.
//
// Node roles come from the target surface itself: an edge is a feature edge when it does not
// have exactly two interface faces or when its faces carry more than one material pair (a
// curve where three materials meet, or where an interface reaches the domain boundary).
// Nodes on no feature edge are surface nodes: they move to the area-weighted mean of their
// faces' centroids, then onto the model facets of their material pair. Nodes on exactly two
// feature edges are curve nodes: they move to the mean of their two curve neighbours, then
// onto the model's feature curves (and stay on the domain boundary when they are on it).
// Other nodes (curve ends and junctions, nodes fixed on the domain boundary) keep their
// target. Every target is first projected onto the model, unless that would make one of its
// quads poor (below `min_projected_quality` and worse than before); then in each sweep (nodes
// in id order, Gauss-Seidel) a smoothed and projected move is kept only when the worst
// quality of the node's target quads does not go down, so the surface's minimum quality
// after the first projection never decreases. A node whose model is farther than
// `search_radius` keeps its target.
#pragma once

#include <array>
#include <string>

#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/quality/scaled_jacobian.h"
#include "hexadapt/reconstruct/model.h"

namespace hexadapt {

struct TargetCorrectionOptions {
  /// true: the guaranteed pipeline corrects the targets when given a model. Off by default:
  /// once the interfaces are pillowed first and nodes slide on their interface, the corrected
  /// targets cost reach and volume on every 3D case measured (docs/results.md).
  bool enabled = false;
  int iterations = 20;      ///< smoothing sweeps over the target surface
  double relaxation = 0.5;  ///< share of the way to the smoothed position per sweep
  /// Model search radius, in mean lengths of the target-surface edges of the input grid.
  double search_radius = 1.5;
  /// A target never moves farther than this from its computed position (in mean edge
  /// lengths): it keeps near the volume fractions' interface.
  double max_shift = 1.0;
  /// The first projection onto the model is refused where it would put a target quad below
  /// this (and below its quality before); such nodes reach the model in the guarded sweeps.
  double min_projected_quality = 0.1;
  /// The quality below which a target quad counts as poor in the result (n_poor_*); the
  /// pipeline sets its threshold.
  double poor_below = default_threshold;
};

struct TargetCorrectionResult {
  bool ran = false;     ///< false: skipped (see `skipped`)
  std::string skipped;  ///< why it did not run ("" when it ran)
  index_t n_faces = 0;  ///< quads of the target surface
  index_t n_surface_nodes = 0, n_curve_nodes = 0, n_fixed_nodes = 0;
  index_t n_unprojected = 0;         ///< nodes with no model within the search radius (kept fixed)
  index_t n_off_model = 0;           ///< movable nodes whose every projection was refused
  double min_quality_before = 1;     ///< worst target-surface quad, computed targets
  double min_quality_projected = 1;  ///< after the first projection onto the model
  double min_quality_after = 1;      ///< after the correction
  index_t n_poor_before = 0, n_poor_after = 0;  ///< quads below poor_below before / after
  double mean_displacement = 0;  ///< mean |corrected - computed| over the interface nodes
  double max_displacement = 0;
  int sweeps = 0;  ///< sweeps run (stops early when no node moves)
};

/// Scaled Jacobian of a quad in space (corners in cyclic order): the minimum over the
/// corners of cross(e_next, e_prev) . n / (|e_next| |e_prev|), n the unit normal of the quad's
/// vector area; -1 for a degenerate quad.
double surface_quad_quality(const std::array<Vec3, 4>& p);

/// Throws OptionError naming the first bad option.
void check_options(const TargetCorrectionOptions& options);

/// Corrects `targets` in place. `material` is the cell assignment, `boundary` the domain
/// boundary constraint of every node; `model` uses the same material indices. Throws
/// InputError when sizes disagree or the model is not 3D, OptionError for bad options.
TargetCorrectionResult correct_targets(const HexMesh& mesh, const CellMaterials& material,
                                       const IdVector<NodeId, NodeConstraint>& boundary,
                                       const reconstruct::InterfaceModel& model, Targets& targets,
                                       const TargetCorrectionOptions& options = {});

}  // namespace hexadapt
