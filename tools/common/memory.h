// Memory: the limit every tool checks its estimate against before the big allocations
// (--max-memory), and the estimates.
//
// A stage's peak memory grows with its input cells; the bytes per cell below are the peaks
// measured on the 3D cases of docs/benchmarks.md (the real3d series: sphere 128^3, 2.1 M
// cells), rounded up. Beyond the limit the tool stops before the work with exit 5, naming
// the estimate; an allocation that fails anyway is exit 5 too, never exit 4.
#pragma once

#include <string>

#include "hexadapt/core/size_text.h"

namespace hexadapt::cli {

/// Peak bytes per input cell of each stage, measured.
inline constexpr double generate_bytes_per_cell = 200;
inline constexpr double assign_bytes_per_cell = 400;
/// adapt: 623 bytes per cell on the sphere 128^3, up to 910 on smaller grids (venn 48^3;
/// vortex 64^3: 836) and per cell held on ranks (the sphere 128^3 on 8 ranks: 870).
inline constexpr double adapt_bytes_per_cell = 1000;
inline constexpr double measure_bytes_per_cell = 500;  ///< per cell of mesh and reference
/// Reconstruct's bytes per input cell besides the pixel estimate (the grid as read, its
/// mesh, the fractions): what a rank's layers weigh beside their pixels when the grid is cut
/// by memory. Fitted to the peaks of the sphere at 96^3 and 128^3 on one process: 181 bytes
/// per cell plus 1.1 times the pixel estimate.
inline constexpr double reconstruct_grid_bytes_per_cell = 200;
/// The same for a rank's part of an unstructured mesh (cut by PT-Scotch), which weighs more
/// while it is merged, cut and moved: about 700 bytes per cell besides the pixels, from
/// assign's peaks on 4 ranks of a 2.1 M-cell jittered hex mesh (342-372 MiB per 520 k cells).
inline constexpr double reconstruct_part_bytes_per_cell = 700;

/// "123", "500M", "8G", "1.5T" (powers of 1000) -> bytes; "" -> physical_memory().
/// Throws OptionError naming --max-memory.
double parse_memory_size(const std::string& text);

/// The machine's physical memory in bytes, or the process's address-space limit (ulimit -v)
/// when lower (0 when neither is known).
double physical_memory();

/// Throws ResourceError when `bytes` exceed `limit`, naming `what`, the estimate and the
/// limit; records the estimate for the out-of-memory message.
void check_memory(const std::string& what, double bytes, double limit);

/// The last estimate checked (0 when none): what an out-of-memory message can name.
double last_memory_estimate();

}  // namespace hexadapt::cli
