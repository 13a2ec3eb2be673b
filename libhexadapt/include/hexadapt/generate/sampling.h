// Sampling: volume fractions of a scene (initial regions + flow) on a quad or hex mesh.
//
// Each cell gets s^d sample points at the centres of an s x s (x s) lattice in its reference
// square (cube), mapped by the bilinear (trilinear) cell map and weighted by the Jacobian
// determinant there (the midpoint rule, so jittered cells get volume-weighted fractions).
// Each sample is traced back through the flow to time 0 (RK4) and classified by the layout.
// Cells whose bounding ball lies farther than the layout's clearance from every interface
// and outside the flow's support are classified by their centre: the result is exactly what
// sampling them would give, only faster. Inside a flow, the mesh points are traced back once
// (each serves the cells around it), and a cell whose image at time 0 (a ball around its
// traced centre, twice as wide as its traced corners reach) is clear of every interface is
// classified by its traced centre: one trace for the cell instead of s^d. Fractions are multiples of 2^-40 with the largest
// one taken as 1 minus the others, so they sum to exactly 1 in any order; a cell whose
// samples all fall in one material is exactly pure. Parallel over cells, each cell on its
// own: the output does not depend on the thread count.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hexadapt/core/log.h"
#include "hexadapt/generate/flows.h"
#include "hexadapt/generate/shapes.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::generate {

/// What is sampled: the regions at time 0 and the flow that moves them (none: static).
struct Scene {
  Layout layout;
  std::shared_ptr<const Flow> flow;
};

struct SamplingOptions {
  int samples = 4;       ///< samples per axis in each cell (s^d per cell), 1..64
  double time = 0;       ///< flow time: samples are traced back from `time` to 0
  int steps = 0;         ///< RK4 steps over [0, time]; 0: automatic_steps(flow, time)
  bool shortcut = true;  ///< classify cells far from every interface by their centre
  Progress progress;     ///< called between blocks of cells, from the calling thread
};

struct SamplingResult {
  Fractions fractions;
  index_t shortcut_cells = 0;  ///< cells classified by the clearance bound
  index_t sampled_cells = 0;   ///< cells whose samples were traced and classified
  index_t mixed_cells = 0;     ///< cells with more than one material
  int steps = 0;               ///< RK4 steps used per sample (0 for a static scene)
  double seconds = 0;
};

/// Fractions on the cells of `mesh` (quads or hexes in kernel order; io::from_mesh makes one
/// from a QuadMesh or HexMesh). `materials` names the layout's material indices in order.
/// Throws OptionError for a bad sample count or more than 16 materials.
SamplingResult sample_fractions(const io::MeshData& mesh, const Scene& scene,
                                const std::vector<std::string>& materials,
                                const SamplingOptions& options);

}  // namespace hexadapt::generate
