#include "hexadapt/core/exact_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace hexadapt {
namespace {

double sum_of(const std::vector<double>& values) {
  ExactSum s;
  for (double v : values) s.add(v);
  return s.value();
}

TEST(ExactSum, AnyOrderAndAnySplitGiveTheSameBits) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-40, 40);
  std::vector<double> v;
  for (int i = 0; i < 5000; ++i) v.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  const double reference = sum_of(v);
  double plain = 0;
  for (double x : v) plain += x;
  EXPECT_NEAR(reference, plain, 1e-9 * std::abs(plain));
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(v.begin(), v.end(), rng);
    EXPECT_EQ(sum_of(v), reference);
    // Split in three parts, added as accumulators in another order.
    const std::size_t a = v.size() / 3, b = 2 * v.size() / 3 + static_cast<std::size_t>(trial);
    ExactSum p0, p1, p2;
    for (std::size_t i = 0; i < v.size(); ++i) (i < a ? p0 : i < b ? p1 : p2).add(v[i]);
    p2.add(p0);
    p2.add(ExactSum::from(p1.canonical(), p1.non_finite()));
    EXPECT_EQ(p2.value(), reference);
  }
}

TEST(ExactSum, KeepsWhatPlainAdditionLoses) {
  EXPECT_EQ(sum_of({1e300, 1.0, -1e300}), 1.0);
  // 0.1 + 0.2 - 0.3 in the doubles' exact values is 2^-55 (plain addition: 2^-54).
  EXPECT_EQ(sum_of({0.1, 0.2, -0.3}), std::ldexp(1.0, -55));
  EXPECT_EQ(sum_of({1.0, std::ldexp(1.0, -80), -1.0}), std::ldexp(1.0, -80));
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(sum_of({tiny, tiny, tiny}), 3 * tiny);
  const double huge = std::numeric_limits<double>::max();
  EXPECT_EQ(sum_of({huge, -huge}), 0);
  EXPECT_EQ(sum_of({huge, huge, -huge}), huge);
  EXPECT_EQ(sum_of({}), 0);
  EXPECT_EQ(sum_of({-2.5, -0.25}), -2.75);
}

TEST(ExactSum, InfinityAndNanPassThrough) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(sum_of({1.0, inf}), inf);
  EXPECT_TRUE(std::isnan(sum_of({inf, -inf})));
  EXPECT_TRUE(std::isnan(sum_of({1.0, std::nan("")})));
}

}  // namespace
}  // namespace hexadapt
