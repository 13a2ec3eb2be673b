// Local non-manifold resolution, the paper's Algorithm 2: the best manifold reassignments
// of the cells around one node.
//
// The candidate materials are those with a fraction > 0 somewhere in the ball, capped at
// the `max_materials` most present (by volume, ties to the lower index). Every cell of the
// ball may take any candidate; a configuration is valid when every material is manifold at
// the node (manifold.h) and costs eq. (4) over the ball. Rather than a blind loop over the
// |M|^k configurations, a depth-first branch and bound assigns the cells in ball order, tries
// each cell's materials from cheapest to dearest, and drops a branch as soon as its cost
// plus the cheapest completion cannot beat the K-th best configuration stored. Ties between
// equal costs follow that fixed order, so the stored set is deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include "hexadapt/assign/configuration_store.h"
#include "hexadapt/assign/local_ball.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

/// What one node's enumeration works with.
struct LocalProblem {
  std::vector<int> materials;  ///< candidates, increasing index
  /// cost[i * materials.size() + j]: eq. (4) of ball cell i taking candidate j
  std::vector<double> cost;
  double volume = 0;  ///< of the whole ball
};

template <class M>
LocalProblem local_problem(const LocalBall<M>& ball, const Fractions& fractions,
                           const IdVector<CellId, double>& volumes, int max_materials);

struct EnumerationStats {
  std::int64_t leaves = 0;           ///< complete configurations examined
  std::int64_t manifold_leaves = 0;  ///< of which valid
  bool truncated = false;            ///< stopped at max_leaves
};

/// Fills `store` with the best manifold configurations (at most max_leaves complete
/// configurations are examined).
template <class M>
EnumerationStats enumerate_configurations(const LocalBall<M>& ball, const LocalProblem& problem,
                                          std::int64_t max_leaves, ConfigurationStore& store);

}  // namespace hexadapt::assign
