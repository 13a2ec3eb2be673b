// decide_tolerances: the sum tolerance and trace threshold follow the stored precision
// unless given (fraction_tolerances.h).
#include "hexadapt/mesh/fraction_tolerances.h"

#include <gtest/gtest.h>

#include <cfloat>

namespace hexadapt {
namespace {

constexpr double eps32 = FLT_EPSILON;

TEST(FractionTolerances, Float64DataTakesTheDefaultsWhateverTheMaterials) {
  for (int n : {1, 3, 200}) {
    const FractionTolerances t = decide_tolerances({}, {}, StoredPrecision::float64, n);
    EXPECT_EQ(t.sum_tolerance, default_sum_tolerance);
    EXPECT_EQ(t.zero_below, default_zero_below);
    EXPECT_EQ(t.float32_rounding, 0);
    EXPECT_FALSE(t.sum_tolerance_given || t.zero_below_given);
  }
}

// The float32 rounding of n fractions is n FLT_EPSILON; the defaults stay at least 8 times
// above it: the float64 ones for few materials, more from 11 (traces) and 105 (sums) on.
TEST(FractionTolerances, Float32DataTakesDefaultsAboveItsRounding) {
  const FractionTolerances three = decide_tolerances({}, {}, StoredPrecision::float32, 3);
  EXPECT_DOUBLE_EQ(three.float32_rounding, 3 * eps32);
  EXPECT_EQ(three.sum_tolerance, default_sum_tolerance);
  EXPECT_EQ(three.zero_below, default_zero_below);
  const FractionTolerances ten = decide_tolerances({}, {}, StoredPrecision::float32, 10);
  EXPECT_EQ(ten.zero_below, default_zero_below);
  const FractionTolerances eleven = decide_tolerances({}, {}, StoredPrecision::float32, 11);
  EXPECT_DOUBLE_EQ(eleven.zero_below, 8 * 11 * eps32);
  EXPECT_GT(eleven.zero_below, default_zero_below);
  EXPECT_EQ(eleven.sum_tolerance, default_sum_tolerance);
  const FractionTolerances many = decide_tolerances({}, {}, StoredPrecision::float32, 105);
  EXPECT_DOUBLE_EQ(many.sum_tolerance, 8 * 105 * eps32);
  EXPECT_GT(many.sum_tolerance, default_sum_tolerance);
  EXPECT_FALSE(many.sum_tolerance_given || many.zero_below_given);
}

TEST(FractionTolerances, GivenValuesWinOverThePrecision) {
  const FractionTolerances t = decide_tolerances(1e-6, 0.0, StoredPrecision::float32, 200);
  EXPECT_EQ(t.sum_tolerance, 1e-6);
  EXPECT_EQ(t.zero_below, 0.0);
  EXPECT_TRUE(t.sum_tolerance_given && t.zero_below_given);
  EXPECT_DOUBLE_EQ(t.float32_rounding, 200 * eps32);  // still reported
  const FractionTolerances one = decide_tolerances(2e-3, {}, StoredPrecision::float64, 3);
  EXPECT_EQ(one.sum_tolerance, 2e-3);
  EXPECT_TRUE(one.sum_tolerance_given);
  EXPECT_EQ(one.zero_below, default_zero_below);
  EXPECT_FALSE(one.zero_below_given);
}

}  // namespace
}  // namespace hexadapt
