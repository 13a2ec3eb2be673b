#include "ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace hexadapt::render {
namespace {

// printf of one number with a run-time precision; + 0.0 turns -0 into 0.
std::string format(const char* pattern, int precision, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, precision, v + 0.0);
  return buf;
}

int exponent(double v) {
  return static_cast<int>(std::floor(std::log10(v)));
}

// The smallest 1, 2 or 5 x 10^e at least `raw` (> 0).
double round_step(double raw) {
  const double unit = std::pow(10.0, exponent(raw));
  for (double m : {1.0, 2.0, 5.0})
    if (m * unit >= raw) return m * unit;
  return 10.0 * unit;
}

// One label format for all multiples of `step`: fixed decimals for ordinary magnitudes,
// otherwise the exponent form with as many mantissa digits as the step needs.
std::string tick_label(double v, double step, double largest) {
  const int e = exponent(step);
  if (step >= 1e-4 && largest < 1e6) return format("%.*f", std::max(0, -e), v);
  const int digits = largest > 0 ? exponent(largest) - e : 0;
  return format("%.*e", std::clamp(digits, 0, 16), v);
}

std::vector<Tick> ends(double lo, double hi) {
  std::vector<Tick> t{{lo, range_label(lo, lo, hi)}};
  if (hi != lo) t.push_back({hi, range_label(hi, lo, hi)});
  return t;
}

// Multiples of `step` inside [lo, hi], the ends allowed a hair of rounding.
std::vector<Tick> multiples(double lo, double hi, double step) {
  const double largest = std::max(std::abs(lo), std::abs(hi));
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  std::vector<Tick> t;
  for (double k = first; k <= last; k += 1.0) {
    std::string label = tick_label(std::clamp(k * step, lo, hi), step, largest);
    // The value the label shows (0.6, not 0.6000000000000001 from 3 x 0.2), kept in range.
    const double v = std::clamp(std::strtod(label.c_str(), nullptr) + 0.0, lo, hi);
    t.push_back({v, std::move(label)});
  }
  return t;
}

}  // namespace

std::vector<Tick> nice_ticks(double lo, double hi, int max_ticks) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
  if (hi < lo) std::swap(lo, hi);
  const double largest = std::max(std::abs(lo), std::abs(hi));
  // Halves first: hi - lo may overflow where hi / 2 - lo / 2 does not.
  const double half_span = hi / 2 - lo / 2;
  if (hi == lo || half_span < 0.5e-12 * largest) return ends(lo, hi);
  max_ticks = std::max(2, max_ticks);
  // Any step from span / (max_ticks - 1) on fits; a smaller one may too, depending on where
  // the range starts (0.456 .. 1 takes 0.1: six ticks from 0.5): up from a tenth of it.
  double step = round_step(half_span / (max_ticks - 1) * 0.2);
  if (!(step > 0) || !std::isfinite(step)) return ends(lo, hi);
  std::vector<Tick> t = multiples(lo, hi, step);
  while (t.size() > static_cast<std::size_t>(max_ticks)) {
    step = round_step(step * 1.5);  // 1 -> 2 -> 5 -> 10
    t = multiples(lo, hi, step);
  }
  return t.empty() ? ends(lo, hi) : t;
}

std::string range_label(double v, double lo, double hi) {
  int digits = 4;
  const double largest = std::max(std::abs(lo), std::abs(hi));
  const double half_span = std::abs(hi / 2 - lo / 2);
  if (half_span > 0 && largest > 0 && std::isfinite(largest))
    digits = std::max(digits, exponent(largest) - exponent(half_span) + 2);
  return format("%.*g", std::min(digits, 17), v);
}

}  // namespace hexadapt::render
