// Cases: the registry of named synthetic inputs of hexadapt-generate (DESIGN sec. 7), each
// with its materials, the dimensions it runs in, and its default grid, bounds and time.
//
// They stand in for the paper's inputs (sec. 6: triple point, double bar, a falling ball,
// an asteroid): analytic shapes, optionally deformed by a divergence-free flow. The
// definitions (centres, radii, flow strengths) are documented in testdata/README.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hexadapt/generate/sampling.h"

namespace hexadapt::generate {

/// An axis-aligned box; 2D cases have lo.z() == hi.z() == 0.
struct Bounds {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
};

/// What a case looks like in one dimension (2 or 3).
struct CaseDefaults {
  bool available = false;
  std::array<int, 3> dims{0, 0, 0};  ///< cells per axis (dims[2] == 0 in 2D)
  Bounds bounds;
  double time = 0;  ///< default flow time (0: static case)
};

struct Case {
  std::string name;
  std::string summary;                 ///< one line, for --list
  std::vector<std::string> materials;  ///< in material index order
  CaseDefaults d2, d3;
  bool has_flow = false;
  /// The scene in dimension dim (2 or 3); the seed drives the seeded shapes (asteroid).
  Scene (*build)(int dim, std::uint64_t seed) = nullptr;

  const CaseDefaults& defaults(int dim) const { return dim == 3 ? d3 : d2; }
  /// The dimension used when none is asked: 2 if available, else 3.
  int default_dim() const { return d2.available ? 2 : 3; }
};

/// Every case, in the order --list shows them.
const std::vector<Case>& cases();
/// Throws OptionError naming the known cases when `name` is not one of them.
const Case& find_case(const std::string& name);

}  // namespace hexadapt::generate
