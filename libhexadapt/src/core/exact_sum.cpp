#include "hexadapt/core/exact_sum.h"

#include <cmath>

namespace hexadapt {

namespace {
constexpr int lowest = -1088;  // weight of digit 0: 2^-1088, below the smallest subnormal
constexpr std::int64_t base = std::int64_t{1} << 32;
}  // namespace

void ExactSum::add(double v) {
  if (!std::isfinite(v)) {
    special_ += v;
    return;
  }
  if (v == 0) return;
  int e = 0;
  const double f = std::frexp(v, &e);                     // v = f 2^e, |f| in [0.5, 1)
  auto m = static_cast<std::int64_t>(std::ldexp(f, 53));  // v = m 2^(e - 53), exact
  int at = e - 53 - lowest;
  while (at < 0) {  // a subnormal: its low bits are zeros
    m /= 2;
    ++at;
  }
  const std::int64_t sign = m < 0 ? -1 : 1;
  const auto magnitude = static_cast<std::uint64_t>(m < 0 ? -m : m);  // < 2^53
  const int shift = at % 32;
  const auto k = static_cast<std::size_t>(at / 32);
  // The 32-bit halves of the magnitude, each shifted into at most two digits.
  const std::uint64_t low = (magnitude & 0xffffffffu) << shift, high = (magnitude >> 32) << shift;
  d_[k] += sign * static_cast<std::int64_t>(low & 0xffffffffu);
  d_[k + 1] += sign * static_cast<std::int64_t>((low >> 32) + (high & 0xffffffffu));
  d_[k + 2] += sign * static_cast<std::int64_t>(high >> 32);
  if (++pending_ == 1 << 29) normalize();
}

void ExactSum::add(const ExactSum& other) {
  const auto o = other.canonical();
  normalize();
  for (std::size_t k = 0; k < d_.size(); ++k) d_[k] += o[k];
  special_ += other.special_;
  normalize();
}

void ExactSum::normalize() {
  for (std::size_t k = 0; k + 1 < d_.size(); ++k) {
    const std::int64_t carry = d_[k] >= 0 ? d_[k] / base : -((-d_[k] + base - 1) / base);
    d_[k] -= carry * base;
    d_[k + 1] += carry;
  }
  pending_ = 0;
}

std::array<std::int64_t, ExactSum::digits> ExactSum::canonical() const {
  ExactSum c = *this;
  c.normalize();
  return c.d_;
}

ExactSum ExactSum::from(const std::array<std::int64_t, digits>& digits_, double non_finite) {
  ExactSum s;
  s.d_ = digits_;
  s.special_ = non_finite;
  s.normalize();
  return s;
}

double ExactSum::value() const {
  if (special_ != 0 || std::isnan(special_)) return special_;
  // In canonical form the last digit carries the sign: a negative sum is summed as its
  // magnitude, whose digits are all in [0, 2^32).
  ExactSum magnitude = *this;
  magnitude.normalize();
  const bool negative = magnitude.d_.back() < 0;
  if (negative) {
    for (std::int64_t& d : magnitude.d_) d = -d;
    magnitude.normalize();
  }
  // Added from the top down: exact until the double's 53 bits are full, then each digit
  // rounds once.
  double sum = 0;
  for (std::size_t k = magnitude.d_.size(); k-- > 0;)
    if (magnitude.d_[k] != 0)
      sum += std::ldexp(static_cast<double>(magnitude.d_[k]), static_cast<int>(32 * k) + lowest);
  return negative ? -sum : sum;
}

}  // namespace hexadapt
