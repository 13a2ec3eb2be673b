// Discrepancy of an output mesh against the input fractions (paper sec. 6.2, eq. 5):
// per input cell c, d_c = sum_m |V(c ∩ M_m) - ma_m(c) V(c)|, from the exact imprint
// (imprint.h); the total is the sum over the cells. Also the volume balance per material:
// what the fractions hold, what the output cells of the material hold, and how much of
// that lies inside the input grid, and each material's volume error relative to its own
// input volume, checked against a bound when one is given (DESIGN sec. 6: every material
// within 1 % of its input volume).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hexadapt/core/ids.h"

namespace hexadapt {

class Fractions;
struct Imprint;

struct MaterialVolume {
  std::string name;
  double input = 0;      ///< sum_c ma_m(c) V(c)
  double output = 0;     ///< volume of the output cells of m
  double imprinted = 0;  ///< sum_c V(c ∩ M_m): the part inside the input grid
  /// (output - input) / input; NaN when input is 0.
  double volume_error() const;
};

struct DiscrepancyOptions {
  /// Every material's |volume_error| must be at most this (materials with no input volume
  /// are skipped); infinity: not checked.
  double max_volume_error = std::numeric_limits<double>::infinity();
};

struct DiscrepancyReport {
  double total = 0;              ///< sum_c d_c
  double input_volume = 0;       ///< sum_c V(c)
  double relative = 0;           ///< total / input_volume
  double max_cell = 0;           ///< max_c d_c
  CellId max_cell_id;            ///< the lowest id reaching it
  std::vector<double> per_cell;  ///< d_c
  std::vector<MaterialVolume> materials;
  double max_volume_error = std::numeric_limits<double>::infinity();  ///< the bound checked
  int worst_material = -1;  ///< largest |volume_error| (-1: no material has input volume)
  int volume_exponent = 0;  ///< the volumes above are in units of 2^volume_exponent (Imprint)
  /// A volume of this report in the grid's units (0 or infinity when not representable).
  double in_grid_units(double volume) const { return std::ldexp(volume, volume_exponent); }
  /// Every material with input volume within max_volume_error.
  bool passed() const;
};

/// Throws InputError when the fractions and the imprint disagree on cells or materials,
/// OptionError when max_volume_error is negative or NaN.
DiscrepancyReport discrepancy(const Imprint& imprint, const Fractions& fractions,
                              const DiscrepancyOptions& options = {});

/// The report (without per_cell) as a JSON object (text), fields in docs/reports.md.
std::string discrepancy_json(const DiscrepancyReport& report);

}  // namespace hexadapt
