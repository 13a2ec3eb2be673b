// Timing of the assignment stage on two large analytic inputs (no files needed):
//   sphere N:        an N^3 hex grid on [0,N]^3, a ball of radius 0.37 N wrapped in a shell
//                    0.75 cells thick (a third material: thin layers are where majority
//                    assignment breaks manifoldness), fractions by sub-sampling the cells
//                    the spheres cross (5^3 points per cell);
//   triple NX NY NZ: NX x NY x NZ hexes on [0,7] x [0,3] (extruded), the three regions of
//                    the triple-point problem rolled up by a vortex at (1, 1.5), fractions
//                    by sub-sampling 4 x 4 points per cell traced back through the vortex.
// Usage: hexadapt_assign_bench [sphere N] [triple NX NY NZ] [--threads T]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hexadapt/assign/assign.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

Fractions sphere_fractions(const HexMesh& mesh, int n) {
  const Vec3 centre(0.5 * n + 0.31, 0.5 * n + 0.17, 0.5 * n + 0.43);
  const double radius = 0.37 * n, reach = std::sqrt(3.0) / 2 + 1e-9;
  const double shell = 0.75;
  Fractions f(mesh.n_cells(), {"sphere", "shell", "outside"});
  auto material = [&](const Vec3& p) {
    const double r = (p - centre).norm();
    return r < radius - shell ? 0 : r < radius ? 1 : 2;
  };
  const int s = 5;
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    const Vec3 lo = mesh.point(mesh.cell_nodes(c)[0]);
    const double d = (lo + Vec3(0.5, 0.5, 0.5) - centre).norm() - radius;
    if (d < -shell - reach || d > reach) {
      f(c, d < 0 ? 0 : 2) = 1;
      return;
    }
    for (int a = 0; a < s; ++a)
      for (int b = 0; b < s; ++b)
        for (int e = 0; e < s; ++e)
          f(c, material(lo + Vec3((a + 0.5) / s, (b + 0.5) / s, (e + 0.5) / s))) +=
              1.0 / (s * s * s);
  });
  return f;
}

int triple_region(double x, double y) {
  // Trace back through a vortex centred on the triple point.
  const double cx = 1, cy = 1.5, dx = x - cx, dy = y - cy;
  const double r = std::sqrt(dx * dx + dy * dy), angle = -4.0 / (r + 0.05) * std::exp(-r * r);
  const double x0 = cx + std::cos(angle) * dx - std::sin(angle) * dy;
  const double y0 = cy + std::sin(angle) * dx + std::cos(angle) * dy;
  if (x0 < 1) return 0;
  return y0 < 1.5 ? 1 : 2;
}

Fractions triple_fractions(const HexMesh& mesh) {
  Fractions f(mesh.n_cells(), {"region1", "region2", "region3"});
  const int s = 4;
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    const auto nodes = mesh.cell_nodes(c);
    const Vec3 lo = mesh.point(nodes[0]), hi = mesh.point(nodes[7]);
    for (int a = 0; a < s; ++a)
      for (int b = 0; b < s; ++b) {
        const double x = lo.x() + (hi.x() - lo.x()) * (a + 0.5) / s;
        const double y = lo.y() + (hi.y() - lo.y()) * (b + 0.5) / s;
        f(c, triple_region(x, y)) += 1.0 / (s * s);
      }
  });
  return f;
}

void report(const char* name, const HexMesh& mesh, double mesh_s, double fractions_s,
            const assign::AssignResult& r) {
  const auto& c = r.correction;
  std::printf("%s: %d cells, %d nodes, %d threads; input: grid %.2f s, fractions %.2f s\n", name,
              mesh.n_cells(), mesh.n_nodes(), n_threads(), mesh_s, fractions_s);
  std::printf(
      "  non-manifold nodes at first %d, solved %s, rounds %d, node solves %d, "
      "cells changed %d, cost added %.4g, configurations examined %lld\n",
      c.non_manifold_initial, c.solved ? "yes" : "NO", c.rounds, c.node_solves, c.cells_changed,
      c.cost_final - c.cost_initial, static_cast<long long>(c.leaves));
  std::printf("  times:");
  for (const auto& [phase, seconds] : r.times) std::printf(" %s %.3f s", phase.c_str(), seconds);
  std::printf("\n");
}

}  // namespace
}  // namespace hexadapt

int main(int argc, char** argv) {
  using namespace hexadapt;
  std::vector<std::string> args(argv + 1, argv + argc);
  bool sphere = false, triple = false;
  int n = 256, nx = 420, ny = 180, nz = 3;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "sphere") {
      sphere = true;
      if (i + 1 < args.size() && std::isdigit(args[i + 1][0])) n = std::stoi(args[++i]);
    } else if (args[i] == "triple") {
      triple = true;
      if (i + 3 < args.size() && std::isdigit(args[i + 1][0])) {
        nx = std::stoi(args[++i]);
        ny = std::stoi(args[++i]);
        nz = std::stoi(args[++i]);
      }
    } else if (args[i] == "--threads" && i + 1 < args.size()) {
      set_threads(std::stoi(args[++i]));
    } else {
      std::fprintf(stderr, "usage: %s [sphere N] [triple NX NY NZ] [--threads T]\n", argv[0]);
      return 1;
    }
  }
  if (!sphere && !triple) sphere = triple = true;
  if (triple) {
    Timer t;
    const double h = 7.0 / nx;
    const HexMesh mesh = make_hex_grid(nx, ny, nz, Vec3::Zero(), Vec3(h, 3.0 / ny, h));
    const double mesh_s = t.seconds();
    t.restart();
    const Fractions f = triple_fractions(mesh);
    report("triple point", mesh, mesh_s, t.seconds(), assign::assign_materials(mesh, f));
  }
  if (sphere) {
    Timer t;
    const HexMesh mesh = make_hex_grid(n, n, n);
    const double mesh_s = t.seconds();
    t.restart();
    const Fractions f = sphere_fractions(mesh, n);
    report("sphere", mesh, mesh_s, t.seconds(), assign::assign_materials(mesh, f));
  }
  return 0;
}
