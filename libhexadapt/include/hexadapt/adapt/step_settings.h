// What the steps of the guaranteed method share: the threshold every cell keeps and how pillow
// nodes start, how nodes smooth and how the domain boundary holds them. AdaptOptions holds
// them once for every step; a step run alone (controlled_move, cavity_pillow,
// pillow_interfaces) takes them beside its own options.
#pragma once

#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/pillow.h"
#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

struct StepSettings {
  double threshold = default_threshold;  ///< S_q every cell keeps
  PillowOptions pillow;                  ///< where pillow nodes start
  SmoothOptions smooth;                  ///< smoothing sweeps
  BoundaryOptions boundary;              ///< feature detection on the domain boundary
};

}  // namespace hexadapt
