#include "hexadapt/generate/jitter.h"

#include <gtest/gtest.h>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::generate {
namespace {

// The kernel checks (a second, independent quality evaluation) on the jittered points.
template <class M>
void expect_jitter_keeps_floor_and_boundary(const M& start, double amplitude, double floor) {
  io::MeshData data = io::from_mesh(start);
  JitterOptions o;
  o.amplitude = amplitude;
  o.min_quality = floor;
  o.seed = 42;
  const auto r = jitter_nodes(data, o);
  const M mesh = std::get<M>(io::to_mesh(data));
  EXPECT_GE(min_quality(mesh), floor);
  EXPECT_EQ(r.min_quality, min_quality(mesh));
  EXPECT_GT(r.moved_nodes, mesh.n_nodes() / 2);
  double total0 = 0, total1 = 0;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    total0 += start.cell_volume(c);
    total1 += mesh.cell_volume(c);
  }
  EXPECT_NEAR(total1, total0, 1e-12 * total0);  // the boundary did not move
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    const Vec3 a = start.point(n), b = mesh.point(n);
    for (int k = 0; k < M::dim; ++k) {
      if (a[k] == 0.0 || a[k] == 4.0) {
        EXPECT_EQ(b[k], a[k]) << "node " << n.value();
      }
    }
  }
}

TEST(Jitter, QuadsKeepTheFloorAndTheBoundary) {
  expect_jitter_keeps_floor_and_boundary(make_quad_grid(20, 20, Vec3::Zero(), Vec3(0.2, 0.2, 1)),
                                         0.3, 0.6);
}

TEST(Jitter, HexesKeepTheFloorAndTheBoundary) {
  expect_jitter_keeps_floor_and_boundary(make_hex_grid(8, 8, 8, Vec3::Zero(), Vec3(0.5, 0.5, 0.5)),
                                         0.3, 0.5);
}

TEST(Jitter, AStrictFloorDampsNodes) {
  io::MeshData mesh = io::from_mesh(make_quad_grid(10, 10));
  JitterOptions o;
  o.amplitude = 0.45;
  o.min_quality = 0.9;
  const auto r = jitter_nodes(mesh, o);
  EXPECT_GT(r.damped_nodes, 0);
  EXPECT_GT(r.moved_nodes, 0);
  EXPECT_GE(min_scaled_jacobian(mesh), 0.9);
}

TEST(Jitter, SameNodesWhateverTheThreadCount) {
  std::vector<std::vector<Vec3>> runs;
  for (int threads : {1, 2}) {
    set_threads(threads);
    io::MeshData mesh = io::from_mesh(make_hex_grid(6, 5, 4));
    jitter_nodes(mesh, JitterOptions{});
    runs.push_back(mesh.points);
  }
  set_threads(0);
  EXPECT_EQ(runs[0], runs[1]);
}

TEST(Jitter, RejectsBadOptions) {
  io::MeshData mesh = io::from_mesh(make_quad_grid(3, 3));
  JitterOptions o;
  o.amplitude = 0.6;
  EXPECT_THROW(jitter_nodes(mesh, o), OptionError);
  o.amplitude = 0.2;
  o.min_quality = 0;
  EXPECT_THROW(jitter_nodes(mesh, o), OptionError);
}

}  // namespace
}  // namespace hexadapt::generate
