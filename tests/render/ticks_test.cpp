// The colour bar's ticks (tools/render/ticks.h) on the ranges a cell array can have.
#ifdef HEXADAPT_HAVE_RENDER
#include "ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace hexadapt::render {
namespace {

std::vector<double> values(const std::vector<Tick>& ticks) {
  std::vector<double> v;
  for (const Tick& t : ticks) v.push_back(t.value);
  return v;
}
std::vector<std::string> labels(const std::vector<Tick>& ticks) {
  std::vector<std::string> v;
  for (const Tick& t : ticks) v.push_back(t.label);
  return v;
}

TEST(RenderTicks, QualityScaleHasTenthsLabelledAlike) {
  const std::vector<Tick> t = nice_ticks(0, 1);
  EXPECT_EQ(values(t), (std::vector<double>{0, 0.2, 0.4, 0.6, 0.8, 1}));
  EXPECT_EQ(labels(t), (std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
}

TEST(RenderTicks, DataRangeStartingAboveItsRoundValues) {
  // The cells' range of a quality picture: ticks at round values inside it, not at 0.
  EXPECT_EQ(labels(nice_ticks(0.456, 1)),
            (std::vector<std::string>{"0.5", "0.6", "0.7", "0.8", "0.9", "1.0"}));
}

// The step between ticks is 1, 2 or 5 times a power of ten (to the rounding of doubles of the
// range's magnitude: a part in 1e6 of a step 1e-8 of the values).
bool is_round_step(double step) {
  const double unit = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (std::abs(step - m * unit) <= 1e-6 * step) return true;
  return false;
}

struct Range {
  double lo, hi;
};

TEST(RenderTicks, AnyRangeGivesRoundDistinctReadableTicksInside) {
  const double big = std::numeric_limits<double>::max();
  const std::vector<Range> ranges = {{0.456, 1},
                                     {-3.7, 12.2},
                                     {-1, 1},
                                     {-5, -2},
                                     {1e-9, 5e-9},
                                     {1e12, 3.5e12},
                                     {1000, 1000.001},
                                     {-2e-5, 3e-4},
                                     {0, 7},
                                     {0, 1e6},
                                     {-big, big},
                                     {1e-310, 5e-310},
                                     {12345.678, 12345.679},
                                     {-0.3, 0}};
  for (const Range& r : ranges) {
    const std::vector<Tick> t = nice_ticks(r.lo, r.hi);
    SCOPED_TRACE(std::to_string(r.lo) + " .. " + std::to_string(r.hi));
    ASSERT_GE(t.size(), 2u);
    ASSERT_LE(t.size(), 6u);
    std::set<std::string> seen;
    for (std::size_t k = 0; k < t.size(); ++k) {
      EXPECT_GE(t[k].value, r.lo);
      EXPECT_LE(t[k].value, r.hi);
      EXPECT_LE(t[k].label.size(), 12u) << t[k].label;
      EXPECT_TRUE(seen.insert(t[k].label).second) << "label repeated: " << t[k].label;
      if (t[k].value == 0) {
        EXPECT_EQ(t[k].label.find('-'), std::string::npos) << t[k].label;
      }
      // The label shows the value (to a part in 1e9 of the step).
      const double step = t.size() > 1 ? t[1].value - t[0].value : 1;
      EXPECT_NEAR(std::strtod(t[k].label.c_str(), nullptr), t[k].value, 1e-9 * std::abs(step))
          << t[k].label;
      if (k == 0) continue;
      const double gap = t[k].value - t[k - 1].value;
      EXPECT_GT(gap, 0);
      EXPECT_NEAR(gap, step, 1e-6 * step);
      EXPECT_TRUE(is_round_step(gap)) << gap;
    }
  }
}

TEST(RenderTicks, FewerTicksWhenFewerFit) {
  for (int n : {2, 3, 4, 5}) {
    const std::vector<Tick> t = nice_ticks(-3.7, 12.2, n);
    EXPECT_GE(t.size(), 1u) << n;
    EXPECT_LE(t.size(), static_cast<std::size_t>(n)) << n;
  }
}

TEST(RenderTicks, ConstantReversedAndNonFiniteRanges) {
  const std::vector<Tick> constant = nice_ticks(2.5, 2.5);
  ASSERT_EQ(constant.size(), 1u);
  EXPECT_EQ(constant[0].value, 2.5);
  EXPECT_EQ(constant[0].label, "2.5");
  EXPECT_EQ(labels(nice_ticks(1, 0)), labels(nice_ticks(0, 1)));
  // Round steps run out of precision 1e-14 apart around 1: the two ends, told apart.
  const std::vector<Tick> ends = nice_ticks(1, 1 + 1e-14);
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_NE(ends[0].label, ends[1].label);
  EXPECT_TRUE(nice_ticks(0, std::numeric_limits<double>::infinity()).empty());
  EXPECT_TRUE(nice_ticks(std::nan(""), 1).empty());
}

TEST(RenderTicks, RangeLabelsTellTheEndsApart) {
  EXPECT_EQ(range_label(0.456, 0.456, 1), "0.456");
  EXPECT_EQ(range_label(1, 0.456, 1), "1");
  EXPECT_EQ(range_label(1000, 1000, 1000.001), "1000");
  EXPECT_EQ(range_label(1000.001, 1000, 1000.001), "1000.001");
  EXPECT_EQ(range_label(-3.7, -3.7, 12.2), "-3.7");
  EXPECT_EQ(range_label(2.5, 2.5, 2.5), "2.5");
}

}  // namespace
}  // namespace hexadapt::render
#endif
