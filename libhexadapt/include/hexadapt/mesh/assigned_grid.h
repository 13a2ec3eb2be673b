// The value the stages pass on from assign to reconstruct, adapt and measure: a grid, the
// volume fraction of every material in every cell, and the one material each cell was given.
// io/assigned_grid_file.h reads it from a file's arrays and writes it back.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

struct AssignedGrid {
  AnyMesh mesh;
  Fractions fractions;     ///< valid and summing to 1 in each cell; the material names
  CellMaterials material;  ///< one per cell; empty for a grid not assigned yet
  const std::vector<std::string>& names() const { return fractions.names(); }
  bool assigned() const { return !material.empty(); }
  /// Throws InputError naming `stage` when the grid has no material per cell.
  void require_assigned(const std::string& stage) const {
    if (!assigned())
      throw InputError("", "",
                       "the grid to " + stage + " has no material per cell (assign it first)");
  }
};

}  // namespace hexadapt
