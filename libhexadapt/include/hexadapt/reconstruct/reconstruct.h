// Interface reconstruction, the whole stage (paper sec. 4, DESIGN sec. 4.2): plan and build
// the sub-pixel mesh, assign its free pixels with one of the four methods, measure edgecut
// and discrepancy, and extract the geometric model. The tool hexadapt-reconstruct is a thin
// layer over reconstruct().
#pragma once

#include <string>
#include <vector>

#include "hexadapt/core/log.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/mesh/assigned_grid.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/annealing.h"
#include "hexadapt/reconstruct/graph_cut.h"
#include "hexadapt/reconstruct/greedy.h"
#include "hexadapt/reconstruct/metrics.h"
#include "hexadapt/reconstruct/mip.h"
#include "hexadapt/reconstruct/model.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

enum class Method { greedy, annealing, graph_cut, mip };
std::string to_string(Method m);
/// "greedy", "annealing", "graphcut", "mip"; throws OptionError otherwise.
Method parse_method(const std::string& name);

struct ReconstructOptions {
  Method method = Method::greedy;  ///< the assignment method (greedy is the paper's choice)
  PixelOptions pixels;             ///< nsub and the memory limit
  GreedyOptions greedy;
  AnnealingOptions annealing;
  GraphCutOptions graph_cut;
  MipOptions mip;
  bool extract_model = true;  ///< also build the geometric model
  Progress progress;          ///< phase progress, nullptr for none
};

struct ReconstructResult {
  PixelPlan plan;
  std::string status = "done";  ///< the method's own status (MIP: optimal / feasible / ...)
  std::int64_t edgecut = 0;
  double discrepancy = 0;              ///< over the pixelated cells
  double unpixelated_discrepancy = 0;  ///< cells without pixels whose assignment is not pure
  double domain_volume = 0;
  /// (discrepancy + unpixelated_discrepancy) / domain_volume, computed before the volumes go
  /// back to the grid's units (where a grid at 1e-300 has no representable volume).
  double relative_discrepancy = 0;
  GreedyResult greedy;
  AnnealingResult annealing;
  GraphCutResult graph_cut;
  MipResult mip;
  PhaseTimes times;
};

struct Reconstruction {
  PixelMesh pixels;
  InterfaceModel model;
  ReconstructResult result;
};

/// Runs the stage on a grid with fractions and a per-cell material assignment.
template <class M>
Reconstruction reconstruct(const M& mesh, const Fractions& fractions,
                           const CellMaterials& assignment, const ReconstructOptions& options);
/// The same on the part of a mesh one rank holds (`where`): the pixels of the held cells, the
/// owned ones assigned as on one process holding the whole mesh when the part has
/// greedy_ghost_layers() layers of ghost cells around the owned ones; the result's figures
/// are the whole mesh's. Greedy only, without the model, on more than one rank (OptionError).
/// Every rank calls it.
template <class M>
Reconstruction reconstruct(const M& mesh, const Fractions& fractions,
                           const CellMaterials& assignment, const ReconstructOptions& options,
                           const dist::Distribution& where);
/// The same on an assigned grid (io::to_assigned_grid); InputError when it has no material.
Reconstruction reconstruct(const AssignedGrid& grid, const ReconstructOptions& options);

}  // namespace hexadapt::reconstruct
