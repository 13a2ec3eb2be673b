// An axis-aligned box of sides a, b, c as a hex's corner points (binary order): the known
// answer the quality tests start from.
#pragma once

#include <array>

#include "hexadapt/core/geometry.h"

namespace hexadapt::test {

inline std::array<Vec3, 8> box_hex(double a, double b, double c) {
  std::array<Vec3, 8> p;
  for (std::size_t v = 0; v < 8; ++v)
    p[v] = Vec3(a * double(v & 1u), b * double((v >> 1) & 1u), c * double((v >> 2) & 1u));
  return p;
}

}  // namespace hexadapt::test
