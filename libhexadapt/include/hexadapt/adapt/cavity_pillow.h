// Cavity pillowing (paper sec. 5.2, Alg. 5): around the nodes the controlled move left short
// of their targets, a cavity of one material is pillowed so that those nodes get a layer of
// new cells to move into.
//
// For each material m and each seed node touching m, the cavity is the cells of m within
// vertex distance `range` of the seed (distance 1: the cells around the seed; k: cells of m
// sharing a node with a cell at distance k - 1). Cavities of the same material that share a
// cell are merged. A cavity is pillowed (pillow_cells), the nodes that only its cells and
// the new layer use are smoothed, and the result is published into the mesh only when every
// cell of the cavity and of its layer reaches the threshold; otherwise each seed whose
// cavity holds a bad cell retries with its range decreased by one, and a seed at range 1
// that still fails is given up (the mesh stays as it was). Greedy: published cavities change
// the mesh the next ones are built in. The cells outside a cavity never change, so no cell
// of the mesh goes below the threshold. Input nodes keep their ids: a seed on the border of
// its cavity stays with the outside cells and keeps its target; its copy inside the cavity
// is a new node without a target. A cavity whose layer cannot be a mesh (cells touching
// along an edge only, joined around both its ends: see pillow.h) is rejected like a poor one,
// and so is a cavity holding a cell around a frozen node (BoundaryOptions::frozen).
//
// Each attempt works in a patch, the cavity and the cells sharing a node with it, and only a
// published cavity is spliced into the mesh: an attempt costs time in the size of its cavity,
// not of the mesh, and the result is the one pillowing the whole mesh gives (whole_mesh).
#pragma once

#include <vector>

#include "hexadapt/adapt/pillow.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/adapt/step_settings.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

struct CavityOptions {
  int range = 3;  ///< vertex distance a cavity starts with
  /// Pillow and smooth each cavity in a copy of the whole mesh instead of in the cavity and
  /// the ring of cells around it: slow, the reference the local patches must reproduce.
  bool whole_mesh = false;
};

/// One pillowing attempt.
struct CavityAttempt {
  int material = 0;
  std::vector<NodeId> seeds;  ///< input node ids
  int range = 0;              ///< the largest range of its seeds
  index_t cells = 0;          ///< cells of the cavity
  bool published = false;
  double min_quality = 0;  ///< smallest score (quality/cell_score.h) of the cavity and its layer
};

template <class M>
struct CavityResult {
  M mesh;
  CellMaterials material;
  IdVector<NodeId, NodeId> node_origin;  ///< the input node each node is (a copy of)
  IdVector<CellId, CellId> cell_origin;  ///< the input cell; a layer cell: its cavity's cell
  std::vector<CavityAttempt> attempts;
  std::vector<NodeId> failed_seeds;  ///< seeds no range could serve, increasing
  index_t n_published = 0;
  index_t n_cells_added = 0;
};

/// `seeds`: node ids of `mesh`; `size`: the size criterion on mesh's cells (off by default). A
/// cavity is published when every cell of it and its layer reaches shared.threshold and the
/// size criterion. Throws OptionError for range < 1.
template <class M>
CavityResult<M> cavity_pillow(const M& mesh, const CellMaterials& material, int n_materials,
                              const std::vector<NodeId>& seeds, const CavityOptions& options = {},
                              const StepSettings& shared = {}, const SizeCriterion& size = {});

}  // namespace hexadapt
