// Graph-cut sub-pixel assignment (paper sec. 4.1.3): alpha-expansion (Boykov, Veksler and
// Zabih 2001) of E(f) = lambda sum_p D_p(f_p) + beta sum_{p,q adjacent} [f_p != f_q] over
// the free pixels, with D_p(f) = (1 - ma_f(cell of p)) * distance from p to the nearest
// fixed pixel of material f (geodesic over the pixel graph, in mean pixel widths).
// Materials absent from a pixel's cell are not allowed there; a material with no fixed pixel
// anywhere costs as much as the farthest one. Each expansion move is an exact min cut by
// Debian's libmaxflow (Boykov-Kolmogorov). Neighbours come from the pixel mesh, in every
// direction. The data term does not enforce the fractions: expect a low edgecut and a high
// discrepancy, as the paper reports (Fig. 7-c).
#pragma once

#include <cstdint>

#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

struct GraphCutOptions {
  double lambda = 1.0;  ///< weight of the data term
  double beta = 1.0;    ///< weight of the smoothness (edgecut) term
  int max_cycles = 10;  ///< expansion cycles over all materials (stops earlier at no gain)
};

struct GraphCutResult {
  int cycles = 0;
  double initial_energy = 0, final_energy = 0;
};

GraphCutResult graph_cut_assign(PixelMesh& pixels, const Fractions& fractions,
                                const GraphCutOptions& options = {});

/// Bytes graph_cut_assign needs per free pixel with n_materials materials.
double graph_cut_bytes_per_free_pixel(int n_materials, int dim);

}  // namespace hexadapt::reconstruct
