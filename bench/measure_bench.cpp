// Times the exact imprint (measure/imprint.h) on the paper's 420x180x3 grid: the grid onto
// itself, a jittered copy (non-planar faces, ~8-27 candidates per cell) onto it, and the
// jittered copy onto a second jittered copy (input cells not convex either, the case of a
// jittered reference grid), with 1 and 2 threads. Prints wall and CPU seconds and the
// volumes, which must add up.
//
//   hexadapt_measure_bench [NX NY NZ [THREADS]]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "hexadapt/core/parallel.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/imprint.h"
#include "hexadapt/mesh/structured.h"

namespace {

using namespace hexadapt;

CellMaterials stripes(index_t n) {
  CellMaterials m(static_cast<std::size_t>(n));
  for (CellId c : id_range<CellId>(n)) m[c] = (c.value() / 7) % 3;
  return m;
}

void run(const char* name, const io::MeshData& in, const io::MeshData& out, int threads) {
  set_threads(threads);
  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  const Imprint im = imprint(in, out, stripes(out.n_cells()), 3);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  double imprinted = 0, cells = 0, output = 0;
  for (double v : im.volume) imprinted += v;
  for (double v : im.cell_volume) cells += v;
  for (double v : im.output_volume) output += v;
  std::printf(
      "%-22s threads %d  wall %7.3f s  cpu %7.3f s  %.3g cells/s  "
      "volume input %.12g output %.12g imprinted %.12g\n",
      name, threads, wall, cpu, in.n_cells() / wall, cells, output, imprinted);
}

}  // namespace

int main(int argc, char** argv) {
  int n[3] = {420, 180, 3};
  std::vector<int> threads = {1, 2};
  if (argc >= 4)
    for (int a = 0; a < 3; ++a) n[a] = std::atoi(argv[a + 1]);
  if (argc == 5) threads = {std::atoi(argv[4])};
  const io::MeshData grid = io::from_mesh(make_hex_grid(n[0], n[1], n[2]));
  std::mt19937 rng(7);
  auto jitter = [&](io::MeshData d) {
    std::uniform_real_distribution<double> u(-0.25, 0.25);
    for (Vec3& p : d.points) {
      // Interior nodes only, so both meshes cover the same box.
      for (int a = 0; a < 3; ++a)
        if (p[a] > 0 && p[a] < n[a]) p[a] += u(rng);
    }
    return d;
  };
  const io::MeshData jittered = jitter(grid), jittered2 = jitter(grid);
  std::printf("%d x %d x %d hexes (%d cells)\n", n[0], n[1], n[2], grid.n_cells());
  for (int t : threads) {
    run("grid onto itself", grid, grid, t);
    run("jittered onto grid", grid, jittered, t);
    run("jittered onto jittered", jittered2, jittered, t);
  }
  return 0;
}
