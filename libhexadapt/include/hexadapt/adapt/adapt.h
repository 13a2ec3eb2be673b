// The mesh adaptation pipelines (paper sec. 5, Fig. 10): from a grid with volume fractions
// and a per-cell material assignment to a conformal mesh whose cells each hold one material
// and whose interfaces follow the fractions.
//
// `base` (Fig. 10-a, Sculpt-like): targets, direct move of the interface nodes onto them,
// global pillowing of every material, global quality-preserving smoothing; no guarantee on
// the output quality (the comparison point of the paper's Table 1). `guaranteed` (Fig. 10-b:
// controlled move, cavity pillowing, move-smooth loop) reuses the same steps and is not
// available yet: asking for it throws OptionError.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/adapt/controlled_move.h"
#include "hexadapt/adapt/global_pillow.h"
#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/adapt/targets.h"
#include "hexadapt/core/log.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

enum class AdaptMethod { base, guaranteed };

/// "base" / "guaranteed"; throws OptionError for another name.
AdaptMethod parse_adapt_method(const std::string& name);
std::string to_string(AdaptMethod method);

struct AdaptOptions {
  AdaptMethod method = AdaptMethod::base;  ///< which pipeline runs
  double threshold = 0.3;                  ///< S_q, the quality the guaranteed method keeps
  int steps = 16;                          ///< steps of the controlled move
  BoundaryOptions boundary;                ///< feature detection on the domain boundary
  TargetOptions targets;                   ///< target computation
  PillowOptions pillow;                    ///< where pillow nodes start
  SmoothOptions smooth;                    ///< smoothing sweeps
  Progress progress;                       ///< phase progress, nullptr = silent
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
  IdVector<CellId, int> material;
  IdVector<NodeId, Vec3> target;  ///< each node's target (its own position when it has none)
  IdVector<NodeId, char> has_target;
  IdVector<NodeId, double> distance;  ///< |position - target|
  std::vector<AdaptStep> steps;
  index_t n_interface_nodes = 0;
  index_t n_reached = 0;          ///< interface nodes on their target at the end
  double dist_init = 0;           ///< sum of distances after the first (controlled or direct) move
  double dist_final = 0;          ///< sum of distances at the end
  double min_quality = 1;         ///< of the output
  index_t n_below_threshold = 0;  ///< output cells with scaled Jacobian < threshold
  index_t n_inverted = 0;         ///< output cells with scaled Jacobian <= 0
};

/// Runs the chosen pipeline. `material` holds one index into `fractions`' materials per
/// cell. Throws InputError for inconsistent sizes, OptionError for bad options.
template <class M>
AdaptResult<M> adapt(const M& grid, const Fractions& fractions,
                     const IdVector<CellId, int>& material, const AdaptOptions& options = {});

}  // namespace hexadapt
