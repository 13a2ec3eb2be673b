// Per-cell size metrics of file data (quality/cell_size.h): the size report's raw values.
#pragma once

#include <vector>

#include "hexadapt/core/log.h"
#include "hexadapt/quality/cell_size.h"

namespace hexadapt {
namespace io {
struct MeshData;
}

/// Edge lengths and time-step length of every cell, indexed by cell.
struct CellSizes {
  std::vector<EdgeLengths> edges;
  std::vector<double> time_step;
};

/// Throws InputError when a cell refers to a missing node. `progress` (phase "size") goes
/// from `from` to `to` over the cells.
CellSizes cell_sizes(const io::MeshData& data, const Progress& progress, double from, double to);

}  // namespace hexadapt
