// Counter-based random numbers: a value is a pure function of (seed, counter), so parallel
// loops draw the same numbers whatever the thread count (SplitMix64 finalizer).
#pragma once

#include <cstdint>

namespace hexadapt::generate::detail {

inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// Uniform in [0, 1) from (seed, stream, index): 53 random bits.
inline double uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
  const std::uint64_t h = mix64(mix64(mix64(seed) ^ stream) ^ index);
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

/// Uniform in [-1, 1).
inline double symmetric(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
  return 2.0 * uniform(seed, stream, index) - 1.0;
}

}  // namespace hexadapt::generate::detail
