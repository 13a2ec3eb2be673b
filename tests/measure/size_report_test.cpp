// The size report on meshes with known answers: a 2x2 grid of unit squares with one node
// moved so that an edge is 0.05 (or 0.2) long, its 3D analogue, local sizes from a
// `local_size` array and from reference grids (a containing cell, the nearest one), the
// same answers in another unit, and the JSON.
#include "hexadapt/measure/size_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

// 2x2 unit squares; node 1, (1, 0), slides along the boundary to (x, 0): cell 0 gets a
// bottom edge x long.
io::MeshData squares(double x) {
  io::MeshData d = io::from_mesh(make_quad_grid(2, 2));
  d.points[1] = Vec3(x, 0, 0);
  return d;
}

// 2x2x2 unit cubes; node 1, (1, 0, 0), slides along its boundary edge to (x, 0, 0).
io::MeshData cubes(double x) {
  io::MeshData d = io::from_mesh(make_hex_grid(2, 2, 2));
  d.points[1] = Vec3(x, 0, 0);
  return d;
}

void set_local_size(io::MeshData& d, double value) {
  io::DataArray a;
  a.name = "local_size";
  a.values.assign(static_cast<std::size_t>(d.n_cells()), value);
  d.set_cell_array(a);
}

void scale(io::MeshData& d, double s, const Vec3& shift) {
  for (Vec3& p : d.points) p = s * p + shift;
}

// Cell 0: (0,0) (0.05,0) (1,1) (0,1), edges 0.05, e = sqrt(0.95^2 + 1), 1, 1, area 0.525.
// Cell 1: (0.05,0) (2,0) (2,1) (1,1), edges 1.95, 1, 1, e, area 1.475. Cells 2, 3: unit.
TEST(SizeReport, SquaresWithAShortEdge) {
  io::MeshData d = squares(0.05);
  set_local_size(d, 1.0);
  const SizeReport r = size_report(d, nullptr);
  const double e = std::sqrt(0.95 * 0.95 + 1);
  EXPECT_EQ(r.local_size, LocalSizeSource::array);
  EXPECT_TRUE(r.checked());
  const SizeFigures& f = r.mesh;
  EXPECT_NEAR(f.edge_ratio.min, 1, 1e-15);
  EXPECT_NEAR(f.edge_ratio.max, e / 0.05, 1e-12);
  EXPECT_NEAR(f.edge_ratio.mean, (1 + 1 + 1.95 + e / 0.05) / 4, 1e-12);
  // Bins [1, 2) holds cells 1, 2, 3 and [16, 32) cell 0 (ratio 27.6).
  EXPECT_EQ(f.edge_ratio_histogram.counts, (std::vector<index_t>{3, 0, 0, 0, 1, 0, 0, 0}));
  EXPECT_NEAR(f.time_step.min, 0.525 / e, 1e-12);
  EXPECT_EQ(f.time_step_min_cell, CellId(0));
  EXPECT_NEAR(f.time_step.max, 1, 1e-15);
  EXPECT_NEAR(f.time_step.mean, (0.525 / e + 1.475 / 1.95 + 2) / 4, 1e-12);
  EXPECT_NEAR(f.time_step_median, 1, 1e-15);
  // Relative to the median: 0.38 in [1/4, 1/2), 0.76 in [1/2, 1), 1 and 1 in [1, 2).
  EXPECT_EQ(f.time_step_histogram.counts, (std::vector<index_t>{0, 0, 0, 0, 0, 1, 1, 2, 0, 0}));
  EXPECT_NEAR(f.min_relative_edge, 0.05, 1e-15);
  EXPECT_NEAR(f.max_relative_edge, 1.95, 1e-15);
  EXPECT_EQ(f.below_min_edge, 1);
  ASSERT_EQ(f.first_below.size(), 1u);
  EXPECT_EQ(f.first_below[0].cell, CellId(0));
  EXPECT_NEAR(f.first_below[0].shortest_edge, 0.05, 1e-15);
  EXPECT_EQ(f.first_below[0].local_size, 1.0);
  EXPECT_NEAR(f.first_below[0].ratio, 0.05, 1e-15);
  EXPECT_NEAR((f.first_below[0].centroid - Vec3(0.2625, 0.5, 0)).norm(), 0, 1e-15);
  EXPECT_FALSE(r.passed());
  SizeReportOptions o;
  o.min_edge = 0.04;
  EXPECT_TRUE(size_report(d, nullptr, o).passed());
  o.min_edge = 0;  // off: measured, not checked
  const SizeReport off = size_report(d, nullptr, o);
  EXPECT_FALSE(off.checked());
  EXPECT_TRUE(off.passed());
  EXPECT_NEAR(off.mesh.min_relative_edge, 0.05, 1e-15);
}

TEST(SizeReport, EdgeOfOneFifthPasses) {
  io::MeshData d = squares(0.2);
  set_local_size(d, 1.0);
  const SizeReport r = size_report(d, nullptr);
  EXPECT_NEAR(r.mesh.min_relative_edge, 0.2, 1e-15);
  EXPECT_EQ(r.mesh.below_min_edge, 0);
  EXPECT_TRUE(r.passed());
}

// Cell 0 of the cubes: edge 0-1 is 0.05 long, the slanted edges 1-3 and 1-5
// e = sqrt(0.95^2 + 1), the other nine 1; the time-step length of a unit cube is 1.
TEST(SizeReport, CubesWithAShortEdge) {
  io::MeshData d = cubes(0.05);
  set_local_size(d, 1.0);
  const SizeReport r = size_report(d, nullptr);
  const double e = std::sqrt(0.95 * 0.95 + 1);
  EXPECT_NEAR(r.mesh.min_relative_edge, 0.05, 1e-15);
  EXPECT_NEAR(r.mesh.edge_ratio.max, e / 0.05, 1e-12);
  EXPECT_NEAR(r.mesh.edge_ratio.min, 1, 1e-15);
  EXPECT_NEAR(r.mesh.time_step.max, 1, 1e-15);
  EXPECT_NEAR(r.mesh.time_step_median, 1, 1e-15);
  EXPECT_EQ(r.mesh.time_step_min_cell, CellId(0));
  EXPECT_EQ(r.mesh.below_min_edge, 1);
  EXPECT_EQ(r.mesh.first_below[0].cell, CellId(0));
  EXPECT_FALSE(r.passed());
  io::MeshData fine = cubes(0.2);
  set_local_size(fine, 1.0);
  EXPECT_TRUE(size_report(fine, nullptr).passed());
}

// Without a local size: the relative figures are absent and the criterion is not checked.
TEST(SizeReport, NoLocalSizeIsNotChecked) {
  const SizeReport r = size_report(squares(0.05), nullptr);
  EXPECT_EQ(r.local_size, LocalSizeSource::none);
  EXPECT_FALSE(r.checked());
  EXPECT_EQ(r.not_checked, "no local_size array and no reference grid");
  EXPECT_TRUE(r.passed());
  EXPECT_FALSE(r.mesh.has_local_size);
  EXPECT_NEAR(r.mesh.edge_ratio.min, 1, 1e-15);  // the rest is measured
}

// A reference of 8x8 cells of side 1/4 over the same square: every local size is 1/4, so
// the short edge is 0.2 local sizes and cell 1's edge of 1.95 is 7.8. An array, when
// present, wins over the reference.
TEST(SizeReport, LocalSizeFromTheReferenceOrTheArray) {
  io::MeshData d = squares(0.05);
  const io::MeshData ref = io::from_mesh(make_quad_grid(8, 8, Vec3::Zero(), Vec3(0.25, 0.25, 1)));
  const SizeReport r = size_report(d, &ref);
  EXPECT_EQ(r.local_size, LocalSizeSource::reference);
  EXPECT_EQ(r.outside_reference, 0);
  EXPECT_NEAR(r.mesh.min_relative_edge, 0.2, 1e-15);
  EXPECT_NEAR(r.mesh.max_relative_edge, 7.8, 1e-15);
  EXPECT_TRUE(r.passed());
  SizeReportOptions o;
  o.min_edge = 0.25;
  EXPECT_FALSE(size_report(d, &ref, o).passed());
  // The reference's own figures: squares of side 1/4, time step 1/4; the mesh's smallest
  // time step is 0.525 / e.
  EXPECT_TRUE(r.has_reference);
  EXPECT_NEAR(r.reference.edge_ratio.max, 1, 1e-15);
  EXPECT_NEAR(r.reference.min_relative_edge, 1, 1e-15);
  EXPECT_NEAR(r.reference.time_step.min, 0.25, 1e-15);
  EXPECT_NEAR(r.time_step_ratio, 0.525 / std::sqrt(0.95 * 0.95 + 1) / 0.25, 1e-12);
  set_local_size(d, 2.0);
  const SizeReport a = size_report(d, &ref);
  EXPECT_EQ(a.local_size, LocalSizeSource::array);
  EXPECT_NEAR(a.mesh.min_relative_edge, 0.025, 1e-15);
}

// The reference has a unit cell and a 2 x 1 one (mean edge 1.5). A mesh cell inside the
// first takes size 1; one beyond the grid takes the cell of the nearest centroid, the second.
TEST(SizeReport, CellOutsideTheReferenceTakesTheNearest) {
  const io::MeshData ref = io::from_mesh(make_quad_grid({0.0, 1.0, 3.0}, {0.0, 1.0}));
  io::MeshData d;
  d.dim = 2;
  d.points = {{0.25, 0.25, 0}, {0.75, 0.25, 0}, {0.75, 0.75, 0}, {0.25, 0.75, 0},
              {3.5, 0, 0},     {4, 0, 0},       {4, 0.5, 0},     {3.5, 0.5, 0}};
  for (int n = 0; n < 8; ++n) d.cells.push_back(NodeId(n));
  SizeReportOptions o;
  o.min_edge = 0.4;
  const SizeReport r = size_report(d, &ref, o);
  EXPECT_EQ(r.outside_reference, 1);
  EXPECT_NEAR(r.mesh.min_relative_edge, 0.5 / 1.5, 1e-15);
  EXPECT_NEAR(r.mesh.max_relative_edge, 0.5, 1e-15);
  ASSERT_EQ(r.mesh.below_min_edge, 1);
  EXPECT_EQ(r.mesh.first_below[0].cell, CellId(1));
  EXPECT_NEAR(r.mesh.first_below[0].local_size, 1.5, 1e-15);
}

// Against a reference of cells of side 1/2, scaled by 1e-300 to 1e300 and moved far away:
// the relative figures and the verdict stay, the lengths scale (at 1e-300 squared lengths
// underflow unless each cell is measured in its own frame).
TEST(SizeReport, SameAnswerInAnyUnit) {
  const io::MeshData ref = io::from_mesh(make_hex_grid(4, 4, 4, Vec3::Zero(), Vec3(0.5, 0.5, 0.5)));
  const SizeReport base = size_report(cubes(0.03), &ref);
  for (double s : {1e-300, 1e-4, 1e5, 1e300}) {
    io::MeshData d = cubes(0.03), g = ref;
    scale(d, s, Vec3(1e3, -2e3, 5e2) * s);
    scale(g, s, Vec3(1e3, -2e3, 5e2) * s);
    const SizeReport r = size_report(d, &g);
    EXPECT_NEAR(r.mesh.min_relative_edge, base.mesh.min_relative_edge, 1e-9) << s;
    EXPECT_NEAR(r.mesh.max_relative_edge, base.mesh.max_relative_edge, 1e-9) << s;
    EXPECT_NEAR(r.mesh.edge_ratio.max, base.mesh.edge_ratio.max, 1e-8) << s;
    EXPECT_NEAR(r.mesh.edge_ratio.mean, base.mesh.edge_ratio.mean, 1e-9) << s;
    EXPECT_NEAR(r.mesh.time_step.min, base.mesh.time_step.min * s, 1e-9 * s) << s;
    EXPECT_NEAR(r.time_step_ratio, base.time_step_ratio, 1e-9) << s;
    EXPECT_EQ(r.mesh.edge_ratio_histogram.counts, base.mesh.edge_ratio_histogram.counts) << s;
    EXPECT_EQ(r.mesh.time_step_histogram.counts, base.mesh.time_step_histogram.counts) << s;
    EXPECT_EQ(r.mesh.below_min_edge, base.mesh.below_min_edge) << s;
    EXPECT_EQ(r.outside_reference, 0) << s;
  }
  EXPECT_NEAR(base.mesh.min_relative_edge, 0.06, 1e-12);  // 0.03 over local size 0.5
  EXPECT_EQ(base.mesh.below_min_edge, 1);
}

TEST(SizeReport, BadInput) {
  io::MeshData d = squares(0.5);
  SizeReportOptions o;
  o.min_edge = -0.1;
  EXPECT_THROW(size_report(d, nullptr, o), OptionError);
  const io::MeshData hexes = io::from_mesh(make_hex_grid(1, 1, 1));
  EXPECT_THROW(size_report(d, &hexes), InputError);
  set_local_size(d, 1.0);
  d.cell_data[0].values[2] = 0;
  try {
    size_report(d, nullptr);
    FAIL() << "a zero local size was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "cell 2 of array 'local_size'");
  }
  EXPECT_THROW(size_report(io::MeshData{}, nullptr), InputError);
}

TEST(SizeReport, Json) {
  io::MeshData d = squares(0.05);
  set_local_size(d, 1.0);
  const io::MeshData ref = io::from_mesh(make_quad_grid(2, 2));
  const auto j = nlohmann::json::parse(size_report_json(size_report(d, &ref)));
  EXPECT_FALSE(j["passed"].get<bool>());
  EXPECT_TRUE(j["checked"].get<bool>());
  EXPECT_FALSE(j.contains("not_checked"));
  EXPECT_EQ(j["local_size"], "array");
  EXPECT_DOUBLE_EQ(j["min_edge"].get<double>(), 0.1);
  EXPECT_EQ(j["below_min_edge"]["count"], 1);
  EXPECT_EQ(j["below_min_edge"]["first"][0]["cell"], 0);
  EXPECT_EQ(j["edge_ratio"]["histogram"]["lower"].size(), 8u);
  EXPECT_EQ(j["time_step"]["histogram"]["counts"].size(), 10u);
  EXPECT_EQ(j["time_step"]["min_cell"], 0);
  EXPECT_NEAR(j["reference"]["time_step"]["min"].get<double>(), 1, 1e-15);
  EXPECT_NEAR(j["time_step_ratio"].get<double>(), 0.525 / std::sqrt(0.95 * 0.95 + 1), 1e-12);
  const auto none = nlohmann::json::parse(size_report_json(size_report(squares(0.05), nullptr)));
  EXPECT_TRUE(none["passed"].get<bool>());
  EXPECT_EQ(none["not_checked"], "no local_size array and no reference grid");
  EXPECT_TRUE(none["local_size"].is_null());
  EXPECT_TRUE(none["relative_edge"].is_null());
  EXPECT_FALSE(none.contains("reference"));
}

}  // namespace
}  // namespace hexadapt
