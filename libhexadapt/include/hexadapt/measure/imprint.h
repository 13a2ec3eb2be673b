// Imprint of an output mesh onto the input grid (paper sec. 6.2, eq. 5; DESIGN sec. 4.4).
//
// For every input cell c and material m, the volume (area in 2D) of c intersected with the
// output cells of material m, exact up to rounding: quads are clipped as polygons, hexes
// are split into 12 tetrahedra (faces split along the diagonal through their lowest global
// node id, so that neighbours agree) and clipped by the half-spaces of the input cell's
// convex pieces (a hex whose folded faces make valleys: its convex hull minus a thin
// tetrahedron per valley face, counted negatively; see cell_pieces.h). A tet is clipped as a
// list of tets (a plane leaves a tet or a prism, split into three), with no cap to build.
// Candidate output cells come from a uniform grid of bins over their bounding boxes. The
// loop runs in parallel over input cells, each writing its own slots, so the result does not
// depend on the thread count. Cost: linear in the cells when the two meshes have similar
// cell sizes.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/core/log.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {
namespace io {
struct MeshData;
}

struct ImprintOptions {
  /// Relative to a cell's diagonal: how far from planar a face, or from convex a cell, may
  /// be and still be clipped as one convex piece (else it is split into tets / triangles).
  double convex_tolerance = 1e-12;
  /// Bins of the candidate grid per output cell (about).
  double bins_per_cell = 1.0;
  /// Called with phase "imprint" and the fraction of input cells done, ending at 1;
  /// nullptr: silent.
  Progress progress;
};

struct Imprint {
  int n_materials = 0;
  index_t n_cells = 0;                ///< input cells
  std::vector<double> volume;         ///< [c * n_materials + m]: V(c ∩ output cells of m)
  std::vector<double> cell_volume;    ///< V(c) (12-tet volume of a hex, area of a quad)
  std::vector<double> output_volume;  ///< per material: total volume of its output cells
  /// Every volume above is in units of 2^volume_exponent: 0, but for grids whose size lies
  /// beyond 2^+-64, whose volumes are measured in their UnitFrame (unit_frame.h) so that they
  /// neither underflow nor overflow (a cell of 1e-300 has a volume of 1e-900).
  int volume_exponent = 0;
  double at(index_t c, int m) const {
    return volume[static_cast<std::size_t>(c) * static_cast<std::size_t>(n_materials) +
                  static_cast<std::size_t>(m)];
  }
};

/// Imprints `output` (material of each output cell in `material`, values in
/// [0, n_materials)) onto the cells of `input`. Both must have the same dimension. Throws
/// InputError (dimension mismatch, a material out of range or of the wrong size).
Imprint imprint(const io::MeshData& input, const io::MeshData& output,
                const CellMaterials& material, int n_materials, const ImprintOptions& options = {});

}  // namespace hexadapt
