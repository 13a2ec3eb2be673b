// The assignment stage (paper sec. 3): majority assignment, small pieces given to the
// materials around them and materials without a cell given some when asked (islands.h,
// keep_materials.h), then manifold correction. This is what hexadapt-assign runs; the steps
// are also available one by one (mesh/fractions.h's majority_materials, islands.h,
// keep_materials.h, manifold.h, enumerate.h, correction.h).
#pragma once

#include <vector>

#include "hexadapt/assign/correction.h"
#include "hexadapt/assign/islands.h"
#include "hexadapt/assign/keep_materials.h"
#include "hexadapt/assign/material_balance.h"
#include "hexadapt/mesh/assigned_grid.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

struct AssignOptions {
  CorrectionOptions correction;
  /// Pieces of one material smaller than this many cells go to a material around them
  /// before the correction (islands.h); 0 or 1: off.
  index_t min_island = 0;
  /// Materials left without a cell take the cells where they are most present, before the
  /// correction (keep_materials.h).
  bool keep_materials = false;
};

struct AssignResult {
  CellMaterials majority;  ///< eq. (2), before correction
  IslandResult islands;    ///< the small pieces reassigned in the majority assignment
  /// Pieces smaller than min_island in the final assignment (the correction may leave some).
  index_t small_pieces_final = 0;
  std::vector<KeptMaterial> kept;  ///< with keep_materials: the materials given cells
  CorrectionResult correction;     ///< labels: the final assignment, with statistics
  PhaseTimes times;                ///< majority, then the correction's phases
  /// Per material, input and assigned volumes of the final assignment (in the grid's units;
  /// shares computed before, so a grid of 1e-300 still has them).
  std::vector<MaterialBalance> balance;
};

template <class M>
AssignResult assign_materials(const M& mesh, const Fractions& fractions,
                              const AssignOptions& options = {});
/// The same on one rank's block of a distributed mesh, every rank calling it with its block
/// (correction.h): the labels of the owned cells and every figure are those of one rank
/// holding the whole mesh, the volumes and costs summed per rank, then in rank order. Small
/// pieces and kept materials need the whole mesh: on more than one rank they throw
/// OptionError.
template <class M>
AssignResult assign_materials(const M& mesh, const Fractions& fractions,
                              const AssignOptions& options, const dist::Distribution& where);

/// The same on a grid read by io::to_assigned_grid (its material, if any, is not read):
/// put the result's correction.labels in grid.material to pass the grid on.
AssignResult assign_materials(const AssignedGrid& grid, const AssignOptions& options = {});

}  // namespace hexadapt::assign
