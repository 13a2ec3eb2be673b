// The exact sum of doubles, whatever order they come in: a fixed-point accumulator wide enough
// for every finite double (2^-1074 to 2^1024), in 32-bit digits. Two accumulators add
// exactly, so a sum split over threads or ranks in any way gives the same exact value, and
// value() turns it into the same double every time (rounded from the most significant digit
// down: within an ulp or so of the exact sum).
#pragma once

#include <array>
#include <cstdint>

namespace hexadapt {

class ExactSum {
 public:
  static constexpr int digits = 68;  ///< 32-bit digits, the lowest of weight 2^-1088

  void add(double v);
  /// Adds another accumulator (the sum of both sets of values).
  void add(const ExactSum& other);
  /// The sum as a double; infinity or NaN when a value added was.
  double value() const;

  /// The digits in canonical form (each in [0, 2^32) but the last, signed), for sending.
  std::array<std::int64_t, digits> canonical() const;
  /// An accumulator from canonical() digits and the non-finite values seen.
  static ExactSum from(const std::array<std::int64_t, digits>& digits_, double non_finite);
  /// The sum of the infinite and NaN values added (0 when none), kept apart from the digits.
  double non_finite() const { return special_; }

 private:
  void normalize();
  std::array<std::int64_t, digits> d_{};
  double special_ = 0;
  int pending_ = 0;  ///< additions since the last normalize (each digit takes up to 2^33)
};

}  // namespace hexadapt
