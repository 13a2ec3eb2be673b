// The measure reports of a mesh spread over the ranks of an MPI job (run under mpirun -np N):
// a jittered hex grid with every kind of defect the mesh check finds (an inverted cell, a
// duplicated node, hanging nodes, a bow-tie), arrays for purity, local sizes and targets, is
// cut into parts two ways (contiguous ranges of cells, and cells scattered over the ranks),
// each part given its ghost layer; the reports computed on the ranks are, as JSON, the
// reports of the whole mesh on one process, character for character; the same for quads.
#include <gtest/gtest.h>

#include <cmath>

#include "hexadapt/io/mesh_part.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/measure/size_report.h"
#include "hexadapt/measure/target_distance.h"
#include "hexadapt/mesh/structured.h"
#include "slab_case.h"

namespace hexadapt {
namespace {

constexpr int gx = 6, gy = 5, gz = 4;  // cells per axis of the grid

index_t grid_node(int i, int j, int k) {
  return static_cast<index_t>(i + (gx + 1) * (j + (gy + 1) * k));
}

// A hex given by its nodes in the kernels' order (x fastest, then y, then z).
void add_cube(io::MeshData& d, const std::array<index_t, 8>& nodes) {
  for (const index_t v : nodes) d.cells.push_back(NodeId(v));
}

index_t add_point(io::MeshData& d, const Vec3& p) {
  d.points.push_back(p);
  return static_cast<index_t>(d.points.size() - 1);
}

// Four half-size cubes on the top face of grid cell (2, 2, gz - 1): the five nodes inside
// that face (edge middles, centre) hang on it.
void add_hanging_block(io::MeshData& d) {
  const std::array<index_t, 4> c = {grid_node(2, 2, gz), grid_node(3, 2, gz), grid_node(3, 3, gz),
                                    grid_node(2, 3, gz)};
  const auto at = [&](double u, double v) {  // the bilinear face at (u, v)
    const auto& p = d.points;
    return (1 - u) * (1 - v) * p[c[0]] + u * (1 - v) * p[c[1]] + u * v * p[c[2]] +
           (1 - u) * v * p[c[3]];
  };
  std::array<std::array<index_t, 3>, 3> low{}, high{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const bool corner = (a != 1) && (b != 1);
      const Vec3 p = at(0.5 * a, 0.5 * b);
      low[a][b] = corner ? c[(a == 0 ? (b == 0 ? 0 : 3) : (b == 0 ? 1 : 2))] : add_point(d, p);
      high[a][b] = add_point(d, p + Vec3(0, 0, 0.5));
    }
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      add_cube(d, {low[a][b], low[a + 1][b], low[a][b + 1], low[a + 1][b + 1], high[a][b],
                   high[a + 1][b], high[a][b + 1], high[a + 1][b + 1]});
}

// The whole mesh, the same on every rank. `scale` multiplies every coordinate.
io::MeshData defective_mesh(double scale) {
  io::MeshData d;
  d.dim = 3;
  for (int k = 0; k <= gz; ++k)
    for (int j = 0; j <= gy; ++j)
      for (int i = 0; i <= gx; ++i) {
        const double g = grid_node(i, j, k);
        const bool inside = i > 0 && i < gx && j > 0 && j < gy && k > 0 && k < gz;
        const Vec3 jitter =
            inside
                ? Vec3(0.2 * Vec3(std::sin(1.3 * g), std::sin(2.1 * g + 1), std::sin(0.7 * g + 2)))
                : Vec3(Vec3::Zero());
        d.points.push_back(Vec3(i, j, k) + jitter);
      }
  std::vector<NodeId> cells;
  append_structured_cells(gx, gy, gz, cells);
  d.cells = cells;
  // An inverted cell: bottom and top swapped.
  std::swap_ranges(d.cells.begin() + 8 * 17, d.cells.begin() + 8 * 17 + 4,
                   d.cells.begin() + 8 * 17 + 4);
  // A duplicated node: cell 40 uses a copy of its first node.
  d.cells[8 * 40] = NodeId(add_point(d, d.points[d.cells[8 * 40].idx()]));
  add_hanging_block(d);
  // A bow-tie: a cube touching the grid at its far corner only.
  const index_t corner = grid_node(gx, gy, gz);
  std::array<index_t, 8> cube{};
  for (int v = 0; v < 8; ++v)
    cube[static_cast<std::size_t>(v)] =
        v == 0 ? corner : add_point(d, d.points[corner] + Vec3(v & 1, (v >> 1) & 1, (v >> 2) & 1));
  add_cube(d, cube);
  for (Vec3& p : d.points) p *= scale;
  const auto n_cells = static_cast<std::size_t>(d.n_cells());
  io::DataArray material{"material", 1, io::ScalarType::float64, {}};
  io::DataArray vf_a{"vf_a", 1, io::ScalarType::float64, {}}, vf_b = vf_a;
  vf_b.name = "vf_b";
  io::DataArray local_size{"local_size", 1, io::ScalarType::float64, {}};
  for (std::size_t c = 0; c < n_cells; ++c) {
    material.values.push_back(c % 23 == 5 ? 2.5 : double(c % 2));
    const double f = c % 7 == 3 ? 0.6 : double(c % 2);
    vf_a.values.push_back(f);
    vf_b.values.push_back(1 - f);
    local_size.values.push_back(scale * (c % 11 == 4 ? 3.0 : 1.0));
  }
  d.cell_data = {material, vf_a, vf_b, local_size};
  io::DataArray target{"target", 3, io::ScalarType::float64, {}};
  for (std::size_t n = 0; n < d.points.size(); ++n)
    for (int k = 0; k < 3; ++k)
      target.values.push_back(n % 3 == 1 ? std::nan("")
                                         : d.points[n][k] + scale * 0.01 * std::sin(double(n + k)));
  d.point_data = {target};
  return d;
}

// The 2D counterpart: a jittered quad grid with folded quads, a duplicated node, two half
// quads on a boundary edge (one node hangs on it) and a quad touching the grid at a corner.
io::MeshData defective_quads() {
  constexpr int qx = 9, qy = 7;
  const auto node = [&](int i, int j) { return static_cast<index_t>(i + (qx + 1) * j); };
  io::MeshData d;
  d.dim = 2;
  for (int j = 0; j <= qy; ++j)
    for (int i = 0; i <= qx; ++i) {
      const double g = node(i, j);
      const bool inside = i > 0 && i < qx && j > 0 && j < qy;
      d.points.emplace_back(i + (inside ? 0.2 * std::sin(1.7 * g) : 0.0),
                            j + (inside ? 0.2 * std::sin(0.9 * g + 1) : 0.0), 0.0);
    }
  std::vector<NodeId> cells;
  append_structured_cells(qx, qy, 0, cells);
  d.cells = cells;
  d.points[node(3, 3)] += Vec3(0.95, 0.95, 0);  // the quads around it fold
  d.cells[4 * 30 + 2] = NodeId(add_point(d, d.points[d.cells[4 * 30 + 2].idx()]));
  // Two half quads on the top edge of cell (4, qy - 1): the edge's middle hangs on it.
  const index_t a = node(4, qy), b = node(5, qy);
  const index_t mid = add_point(d, 0.5 * (d.points[a] + d.points[b]));
  const index_t a_up = add_point(d, d.points[a] + Vec3(0, 0.5, 0));
  const index_t mid_up = add_point(d, d.points[mid] + Vec3(0, 0.5, 0));
  const index_t b_up = add_point(d, d.points[b] + Vec3(0, 0.5, 0));
  for (const index_t v : {a, mid, mid_up, a_up, mid, b, b_up, mid_up}) d.cells.push_back(NodeId(v));
  // A bow-tie at the grid's far corner.
  const index_t corner = node(qx, qy);
  const index_t c1 = add_point(d, d.points[corner] + Vec3(1, 0, 0));
  const index_t c2 = add_point(d, d.points[corner] + Vec3(1, 1, 0));
  const index_t c3 = add_point(d, d.points[corner] + Vec3(0, 1, 0));
  for (const index_t v : {corner, c1, c2, c3}) d.cells.push_back(NodeId(v));
  io::DataArray material{"material", 1, io::ScalarType::float64, {}};
  for (index_t c = 0; c < d.n_cells(); ++c) material.values.push_back(c % 17 == 2 ? -1.0 : 0.0);
  d.cell_data = {material};
  return d;
}

// Cells [first, end) of `whole` with the nodes they use, as a rank's part.
io::MeshPart range_part(const io::MeshData& whole, std::int64_t first, std::int64_t end) {
  const auto npc = static_cast<std::size_t>(whole.nodes_per_cell());
  io::MeshPart part;
  part.n_cells = whole.n_cells();
  part.n_nodes = whole.n_points();
  std::vector<std::int64_t> used;
  for (auto c = static_cast<std::size_t>(first); c < static_cast<std::size_t>(end); ++c)
    for (std::size_t v = 0; v < npc; ++v) used.push_back(whole.cells[c * npc + v].value());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  part.node_ids = used;
  io::MeshData& d = part.data;
  d.dim = whole.dim;
  for (const std::int64_t g : used) d.points.push_back(whole.points[static_cast<std::size_t>(g)]);
  for (auto c = static_cast<std::size_t>(first); c < static_cast<std::size_t>(end); ++c) {
    part.cell_ids.push_back(static_cast<std::int64_t>(c));
    for (std::size_t v = 0; v < npc; ++v) {
      const auto it = std::lower_bound(used.begin(), used.end(), whole.cells[c * npc + v].value());
      d.cells.push_back(NodeId(it - used.begin()));
    }
  }
  for (const io::DataArray& a : whole.cell_data) {
    io::DataArray s = a;
    s.values.assign(a.values.begin() + first * a.n_components,
                    a.values.begin() + end * a.n_components);
    d.cell_data.push_back(s);
  }
  for (const io::DataArray& a : whole.point_data) {
    io::DataArray s = a;
    s.values.clear();
    for (const std::int64_t g : used)
      for (int k = 0; k < a.n_components; ++k)
        s.values.push_back(a.values[static_cast<std::size_t>(g * a.n_components + k)]);
    d.point_data.push_back(s);
  }
  return part;
}

// This rank's contiguous share of the cells.
io::MeshPart contiguous(const io::MeshData& whole) {
  const std::int64_t n = whole.n_cells(), r = test::world().rank(), s = test::world().size();
  return range_part(whole, n * r / s, n * (r + 1) / s);
}

// The cells scattered: cell c goes to rank (c / 5 + c % 3) mod size; the cells from `tail`
// on to the last rank.
io::MeshPart scattered(const io::MeshData& whole, std::int64_t tail = -1) {
  const io::MeshPart part = contiguous(whole);
  const int size = test::world().size();
  std::vector<int> to;
  for (const std::int64_t c : part.cell_ids)
    to.push_back(tail >= 0 && c >= tail ? size - 1 : static_cast<int>((c / 5 + c % 3) % size));
  return io::migrate(test::world(), part, to);
}

void expect_reports_of_whole(const io::MeshData& whole, const io::MeshPart& owned, int listed) {
  const io::GhostedPart part = io::with_ghost_layers(test::world(), owned);
  QualityReportOptions quality;
  quality.threshold = 0.8;
  quality.max_listed = listed;
  quality.check.max_listed = listed;
  EXPECT_EQ(quality_report_json(quality_report(test::world(), part, quality)),
            quality_report_json(quality_report(whole, quality)));
  SizeReportOptions size;
  size.min_edge = 0.5;
  size.max_listed = listed;
  EXPECT_EQ(size_report_json(size_report(test::world(), part, size)),
            size_report_json(size_report(whole, nullptr, size)));
  EXPECT_EQ(target_distances_json(target_distances(test::world(), part)),
            target_distances_json(target_distances(whole)));
}

TEST(MeasureOnRanks, TheWholeMeshReportsOnEveryRank) {
  const io::MeshData whole = defective_mesh(1.0);
  // The case holds what it claims (the whole mesh's own check).
  const QualityReport r = quality_report(whole);
  ASSERT_TRUE(r.topology_error.empty());
  EXPECT_EQ(r.check.inverted_cells, 1);
  EXPECT_EQ(r.check.duplicate_nodes, 1);
  EXPECT_EQ(r.check.hanging_nodes, 5);
  EXPECT_GE(r.check.nonmanifold_nodes, 1);
  EXPECT_GT(r.purity.invalid_material_cells, 3);
  EXPECT_GT(r.purity.mixed_cells, 3);
  for (const int listed : {2, 100}) {
    expect_reports_of_whole(whole, contiguous(whole), listed);
    expect_reports_of_whole(whole, scattered(whole), listed);
  }
}

TEST(MeasureOnRanks, QuadsTheSameAsOneProcess) {
  const io::MeshData whole = defective_quads();
  const QualityReport r = quality_report(whole);
  ASSERT_TRUE(r.topology_error.empty()) << r.topology_error;
  EXPECT_GE(r.check.inverted_cells, 1);
  EXPECT_EQ(r.check.duplicate_nodes, 1);
  EXPECT_EQ(r.check.hanging_nodes, 1);
  EXPECT_GE(r.check.nonmanifold_nodes, 1);
  expect_reports_of_whole(whole, contiguous(whole), 100);
  expect_reports_of_whole(whole, scattered(whole), 2);
  // The half quads on the last rank, the quad whose edge their node hangs on (58) on rank 0
  // (12 mod 2, 3 or 4): the hanging node is found across the ranks' border.
  expect_reports_of_whole(whole, scattered(whole, 9 * 7), 100);
}

TEST(MeasureOnRanks, FarFromUnitSizeTheSameAsOneProcess) {
  for (const double scale : {1e-300, 1e300}) {
    const io::MeshData whole = defective_mesh(scale);
    expect_reports_of_whole(whole, scattered(whole), 5);
  }
}

TEST(MeasureOnRanks, AFaceOfThreeCellsIsATopologyErrorOnEveryRank) {
  io::MeshData whole = defective_mesh(1.0);
  // A cube on top of grid cell 0's top face... and another on the same face.
  std::array<index_t, 8> cube{};
  const auto& top = std::array<index_t, 4>{grid_node(0, 0, 1), grid_node(1, 0, 1),
                                           grid_node(1, 1, 1), grid_node(0, 1, 1)};
  for (int v = 0; v < 4; ++v) cube[static_cast<std::size_t>(v)] = top[static_cast<std::size_t>(v)];
  for (int v = 4; v < 8; ++v)
    cube[static_cast<std::size_t>(v)] =
        add_point(whole, whole.points[top[static_cast<std::size_t>(v - 4)]] + Vec3(0, 0, -0.5));
  add_cube(whole, cube);
  for (io::DataArray& a : whole.cell_data) a.values.push_back(1.0);
  for (io::DataArray& a : whole.point_data)
    a.values.resize(static_cast<std::size_t>(whole.n_points() * a.n_components), 0.0);
  ASSERT_FALSE(quality_report(whole).topology_error.empty());
  const io::GhostedPart part = io::with_ghost_layers(test::world(), scattered(whole));
  const QualityReport r = quality_report(test::world(), part);
  EXPECT_FALSE(r.topology_error.empty());
  EXPECT_FALSE(r.passed());
}

}  // namespace
}  // namespace hexadapt
