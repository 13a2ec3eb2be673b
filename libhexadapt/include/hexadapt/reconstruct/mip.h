// Mixed-integer programme for the sub-pixel assignment (paper sec. 4.1.1), solved by GLPK.
//
//   minimise   sum_{p,k} t_{p,k}
//   subject to t_{p,k} >= c_{p,k} - mean_{q in N(p)} c_{q,k},  t_{p,k} >= -(...)
//              sum_k c_{p,k} = 1                      for every free pixel p
//              sum_{p in cc} c_{p,k} = n_k(cc)        for every mixed cell cc, material k
//              c_{p,k} in {0, 1}
// where n_k(cc) is the largest-remainder rounding of nsub^d * ma_k(cc) (so the counts always
// sum to nsub^d and the constraints are consistent) and neighbours that are fixed pixels enter
// as constants. Only materials present in a cell get variables there. The solve stops at
// the time limit: the status says whether the answer is proven optimal, only feasible, or
// whether no solution was found (the pixels then keep the largest-remainder fill, which
// satisfies the constraints). GLPK's terminal output goes to the library log (debug).
// GLPK is single-threaded and deterministic, but a time limit makes results depend on speed.
#pragma once

#include <string>

#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

struct MipOptions {
  double time_limit = 60;   ///< seconds given to GLPK's branch and cut
  double mip_gap = 0;       ///< relative gap at which GLPK may stop (0: prove optimality)
  std::uint64_t seed = 1;   ///< seed of the fallback fill handed to GLPK as a first incumbent
};

enum class MipStatus { optimal, feasible, timed_out_no_solution, no_free_pixels };
std::string to_string(MipStatus s);

struct MipResult {
  MipStatus status = MipStatus::no_free_pixels;
  int n_variables = 0, n_constraints = 0;
  double objective = 0;    ///< of the solution kept
  double best_bound = 0;   ///< GLPK's lower bound on the optimum
  double seconds = 0;
};

MipResult mip_assign(PixelMesh& pixels, const Fractions& fractions, const MipOptions& options = {});

/// Bytes the GLPK model needs per free pixel (rough: GLPK's rows, columns and matrix).
double mip_bytes_per_free_pixel(int n_materials, int dim);

}  // namespace hexadapt::reconstruct
