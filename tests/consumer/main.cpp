// Uses the installed library as README.md shows: builds small hex grids and checks their
// minimum scaled Jacobian against known answers, then writes one to a zlib-compressed .vtu
// and reads it back, which needs the library's private dependencies (zlib, pugixml) to come
// with the package. Exit code 0 when all match, 1 otherwise.
#include <cmath>
#include <cstdio>
#include <exception>
#include <variant>
#include <vector>

#include <hexadapt/io/mesh_data.h>
#include <hexadapt/io/mesh_file.h>
#include <hexadapt/mesh/cell_complex.h>
#include <hexadapt/mesh/structured.h>

namespace {

// Min scaled Jacobian of `mesh` after a trip through a compressed .vtu file.
double through_vtu(const hexadapt::HexMesh& mesh, const char* path) {
  hexadapt::io::WriteOptions options;
  options.compress_above = 0;  // compress every array
  hexadapt::io::write_mesh(hexadapt::io::from_mesh(mesh), path, options);
  const hexadapt::AnyMesh back = hexadapt::io::to_mesh(hexadapt::io::read_mesh(path));
  if (!std::holds_alternative<hexadapt::HexMesh>(back)) return -2;
  const auto& hexes = std::get<hexadapt::HexMesh>(back);
  return hexes.n_cells() == mesh.n_cells() ? hexadapt::min_quality(hexes) : -2;
}

}  // namespace

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

  try {
    const double qv = through_vtu(sheared, "sheared.vtu");
    std::printf("sheared, through sheared.vtu: min scaled Jacobian %.15f\n", qv);
    good = good && qv == qs;
  } catch (const std::exception& e) {
    std::printf("writing and reading sheared.vtu failed: %s\n", e.what());
    good = false;
  }

  std::printf("%s\n", good ? "ok" : "WRONG");
  return good ? 0 : 1;
}
