// Uses the installed library: builds two small hex grids and checks their minimum scaled
// Jacobian against known answers. Exit code 0 when both match, 1 otherwise.
#include <cmath>
#include <cstdio>
#include <vector>

#include <hexadapt/mesh/cell_complex.h>
#include <hexadapt/mesh/structured.h>

namespace {

bool check(const char* what, double value, double expected) {
  const bool good = std::abs(value - expected) < 1e-12;
  std::printf("%s: min scaled Jacobian %.15f (expected %.15f)%s\n", what, value, expected,
              good ? "" : "  WRONG");
  return good;
}

}  // namespace

int main() {
  // A Cartesian grid: every cell is a box, scaled Jacobian 1.
  const hexadapt::HexMesh grid = hexadapt::make_hex_grid(4, 3, 2);
  bool good = grid.n_cells() == 24 && grid.n_nodes() == 60;
  good = check("cartesian 4x3x2", hexadapt::min_quality(grid), 1.0) && good;

  // The same grid sheared by x += z: parallelepipeds with edges (1,0,0), (0,1,0), (1,0,1),
  // whose scaled Jacobian is 1 / sqrt(2) at every corner and at the centre.
  std::vector<hexadapt::Vec3> points;
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 4; ++i) points.emplace_back(i + k, j, k);
  const hexadapt::HexMesh sheared = hexadapt::make_hex_grid(4, 3, 2, points);
  good = check("sheared 4x3x2", hexadapt::min_quality(sheared), 1.0 / std::sqrt(2.0)) && good;
  return good ? 0 : 1;
}
