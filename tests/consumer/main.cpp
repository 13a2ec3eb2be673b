// Uses the installed library as README.md shows: builds small hex grids and checks their
// minimum scaled Jacobian against known answers. Exit code 0 when all match, 1 otherwise.
#include <cmath>
#include <cstdio>
#include <vector>

#include <hexadapt/mesh/cell_complex.h>
#include <hexadapt/mesh/structured.h>

int main() {
  const hexadapt::HexMesh grid = hexadapt::make_hex_grid(4, 3, 2);  // 4 x 3 x 2 unit cubes
  const double q = hexadapt::min_quality(grid);                     // min scaled Jacobian
  std::printf("%d cells, min scaled Jacobian %g\n", grid.n_cells(), q);
  bool good = grid.n_cells() == 24 && grid.n_nodes() == 60 && std::abs(q - 1.0) < 1e-12;

  // The same grid sheared by x += z: parallelepipeds with edges (1,0,0), (0,1,0), (1,0,1),
  // whose scaled Jacobian is 1 / sqrt(2) at every corner and at the centre.
  std::vector<hexadapt::Vec3> points;
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 4; ++i) points.emplace_back(i + k, j, k);
  const hexadapt::HexMesh sheared = hexadapt::make_hex_grid(4, 3, 2, points);
  const double qs = hexadapt::min_quality(sheared);
  std::printf("sheared: min scaled Jacobian %.15f (expected %.15f)\n", qs, 1 / std::sqrt(2.0));
  good = good && std::abs(qs - 1 / std::sqrt(2.0)) < 1e-12;

  std::printf("%s\n", good ? "ok" : "WRONG");
  return good ? 0 : 1;
}
