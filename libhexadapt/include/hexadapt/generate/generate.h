// Generate: one named case (cases.h) on a grid, as the data of a mesh file with one
// `vf_<material>` cell array per material (DESIGN sec. 2 and 7). The library side of
// hexadapt-generate: build the grid, optionally jitter it (jitter.h), sample the fractions
// (sampling.h) and optionally extrude a 2D case into hex layers (extrusion.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "hexadapt/core/log.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/generate/cases.h"
#include "hexadapt/generate/jitter.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::generate {

struct GenerateOptions {
  std::string case_name;         ///< one of cases()
  std::vector<int> dims;         ///< cells per axis, 2 (2D) or 3 (3D) values; empty: default
  std::optional<Bounds> bounds;  ///< domain box; unset: the case's default
  std::optional<double> time;    ///< flow time; unset: the case's default
  int samples = 4;               ///< samples per axis and cell (s^d per cell)
  int steps = 0;                 ///< RK4 steps over [0, time]; 0: automatic
  int extrude = 0;               ///< > 0: a 2D case swept into this many hex layers
  double jitter = 0;             ///< node displacement amplitude (jitter.h), 0: none
  double jitter_floor = 0.5;     ///< scaled Jacobian every jittered cell keeps
  std::uint64_t seed = 1;        ///< seeds the jitter and the seeded shapes
  Progress progress;             ///< sampling progress
};

struct GenerateResult {
  io::MeshData data;  ///< points, cells, vf_<material> arrays, metadata
  int dim = 0;        ///< dimension the case was sampled in
  double time = 0;    ///< flow time used
  int steps = 0;      ///< RK4 steps per sample (0: static)
  index_t shortcut_cells = 0, sampled_cells = 0, mixed_cells = 0;  ///< of the sampled mesh
  std::vector<std::string> materials;
  std::vector<double> volumes;  ///< per material, of the output mesh
  JitterResult jitter;
  double min_quality = 1;  ///< smallest scaled Jacobian of the output cells
  PhaseTimes times;
};

/// Throws OptionError for an unknown case, a dimension the case does not have, bad dims,
/// bounds or option values.
GenerateResult generate(const GenerateOptions& options);

}  // namespace hexadapt::generate
