#include "hexadapt/mesh/fraction_tolerances.h"

#include <algorithm>
#include <cfloat>

namespace hexadapt {

const char* precision_name(StoredPrecision p) {
  return p == StoredPrecision::float32 ? "float32" : "float64";
}

FractionTolerances decide_tolerances(std::optional<double> sum_tolerance,
                                     std::optional<double> zero_below, StoredPrecision precision,
                                     int n_materials) {
  FractionTolerances t;
  if (precision == StoredPrecision::float32)
    t.float32_rounding = std::max(n_materials, 1) * static_cast<double>(FLT_EPSILON);
  const double floor = float32_margin * t.float32_rounding;
  t.sum_tolerance_given = sum_tolerance.has_value();
  t.sum_tolerance = sum_tolerance.value_or(std::max(default_sum_tolerance, floor));
  t.zero_below_given = zero_below.has_value();
  t.zero_below = zero_below.value_or(std::max(default_zero_below, floor));
  return t;
}

}  // namespace hexadapt
