// The sum tolerance and trace threshold extract_fractions (io/fractions_reader.h) judges a file's
// fractions with: given in the options, or decided here from the precision the fractions
// were stored in. One place decides them, so every tool reads a file the same way.
//
// Float32 rounding. A fraction v <= 1 stored as float32 is off by at most 2^-24 (half an
// ulp of [0.5, 1)); the sum of a cell's n stored fractions by n 2^-24. A solver that computed
// the fractions in float32 and normalised them there added as much again (n - 1 additions
// and a division, each within 2^-24), and a fraction it meant as 0 (a remainder 1 - sum of
// the others) comes out within that too. The float32 rounding of a cell is therefore bounded
// by n 2^-23 = n FLT_EPSILON. With a margin of 8 (a few more float32 operations per value),
// the defaults for float32 data are never below 8 n FLT_EPSILON (2.9e-6 for 3 materials).
//
// That bound is far below the float64 defaults, which stand for the solver's own noise
// (sums off by ~1e-6 and traces of ~1e-6 in real output, with a margin): so the float32
// defaults are the larger of the two, and they differ from the float64 ones only from
// 11 materials on (trace threshold) and 105 on (sum tolerance). A float32 file whose sums are
// off by 1e-3 is not rounding (that is ~10^4 ulps): its solver did not keep the sum, and only
// the user can accept that, with an explicit sum tolerance.
#pragma once

#include <optional>

namespace hexadapt {

/// How the fraction values were stored in their file (io::DataArray::type).
enum class StoredPrecision {
  float64,  ///< double, or exact (integers, text as written, label maps)
  float32,  ///< single precision: at least one fraction array read was float32
};

/// "float32" or "float64".
const char* precision_name(StoredPrecision p);

struct FractionTolerances {
  double sum_tolerance = 0;          ///< how far from 1 a cell's sum may be and be rescaled
  double zero_below = 0;             ///< fractions below this are traces and become 0
  bool sum_tolerance_given = false;  ///< from the options; false: decided from the precision
  bool zero_below_given = false;     ///< from the options; false: decided from the precision
  /// Bound of the float32 rounding of a cell's stored fractions (n_materials FLT_EPSILON);
  /// 0 for float64 data.
  double float32_rounding = 0;
};

/// Defaults for float64 data: the solver's noise, not its precision.
constexpr double default_sum_tolerance = 1e-4;
constexpr double default_zero_below = 1e-5;
/// Float32 defaults are at least this many times the float32 rounding of a cell.
constexpr double float32_margin = 8;

/// The tolerances for `n_materials` fractions read as `precision`: a given value (set
/// optional) is kept whatever the precision; an unset one is the float64 default, or for
/// float32 data the larger of it and float32_margin x the float32 rounding of a cell.
FractionTolerances decide_tolerances(std::optional<double> sum_tolerance,
                                     std::optional<double> zero_below, StoredPrecision precision,
                                     int n_materials);

}  // namespace hexadapt
