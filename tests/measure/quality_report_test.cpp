// The quality report: statistics, histogram, threshold, check, purity and JSON on meshes
// with known values.
#include "hexadapt/measure/quality_report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/structured.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {
namespace {

// Two unit quads side by side; the right one is the kite of quad_quality_test with t = 2
// (scaled Jacobian 0.6): its corner (2, 1) pulled to (3, 2) relative to (1, 0).
io::MeshData two_quads() {
  io::MeshData d = io::from_mesh(make_quad_grid(2, 1));
  d.points[5] = Vec3(3, 2, 0);
  return d;
}

io::DataArray cell_array(const std::string& name, std::vector<double> v) {
  io::DataArray a;
  a.name = name;
  a.values = std::move(v);
  return a;
}

TEST(QualityReport, StatisticsAndHistogram) {
  const io::MeshData d = two_quads();
  QualityReportOptions o;
  o.bins = 10;
  o.threshold = 0.7;
  const QualityReport r = quality_report(d, o);
  EXPECT_EQ(r.dim, 2);
  EXPECT_EQ(r.n_cells, 2);
  EXPECT_EQ(r.n_nodes, 6);
  EXPECT_NEAR(r.scaled_jacobian.min, 0.6, 1e-12);
  EXPECT_NEAR(r.scaled_jacobian.max, 1.0, 1e-15);
  EXPECT_NEAR(r.scaled_jacobian.mean, 0.8, 1e-12);
  EXPECT_NEAR(r.shape.max, 1.0, 1e-15);
  EXPECT_LT(r.shape.min, 1.0);
  // Bins of width 0.2 over [-1, 1]: 0.6 falls in [0.6, 0.8) (bin 8), 1 in the last, closed one.
  ASSERT_EQ(r.histogram.counts.size(), 10u);
  EXPECT_EQ(r.histogram.counts[8], 1);
  EXPECT_EQ(r.histogram.counts[9], 1);
  EXPECT_EQ(r.below_threshold, 1);
  ASSERT_EQ(r.first_below.size(), 1u);
  EXPECT_EQ(r.first_below[0].cell, CellId(1));
  EXPECT_FALSE(r.quality_ok());
  EXPECT_TRUE(r.check_ok());
  EXPECT_FALSE(r.passed());
  o.threshold = 0.6;  // "at least the threshold" passes
  EXPECT_TRUE(quality_report(d, o).passed());
}

TEST(QualityReport, InvertedCellFailsTheCheck) {
  io::MeshData d = io::from_mesh(make_hex_grid(2, 2, 2));
  d.points[13] = Vec3(2.5, 2.5, 2.5);  // the centre node beyond the far corner
  const QualityReport r = quality_report(d, {});
  EXPECT_LT(r.scaled_jacobian.min, 0);
  EXPECT_GT(r.check.inverted_cells, 0);
  EXPECT_FALSE(r.check_ok());
}

TEST(QualityReport, UnrepresentableTopologyIsAFailedCheck) {
  // Three hexes on one face: the kernel refuses it, the report says so.
  const HexMesh column = make_hex_grid(1, 1, 2);
  io::MeshData d = io::from_mesh(column);
  for (int v = 0; v < 4; ++v) {
    d.points.push_back(d.points[d.cells[8 + 4 + static_cast<std::size_t>(v)].idx()] +
                       Vec3(0, 0, 5));
  }
  for (int v = 0; v < 8; ++v) {
    const NodeId n = d.cells[8 + static_cast<std::size_t>(v)];
    d.cells.push_back(v < 4 ? n : NodeId(static_cast<index_t>(12 + v - 4)));
  }
  const QualityReport r = quality_report(d, {});
  EXPECT_EQ(r.n_cells, 3);
  EXPECT_FALSE(r.topology_error.empty());
  EXPECT_FALSE(r.check_ok());
  EXPECT_FALSE(r.passed());
  EXPECT_NEAR(r.scaled_jacobian.max, 1.0, 1e-12);
  const auto j = nlohmann::json::parse(quality_report_json(r));
  EXPECT_FALSE(j["mesh_check"]["representable"].get<bool>());
  EXPECT_NE(j["mesh_check"]["error"].get<std::string>().find("shared by"), std::string::npos);
}

TEST(QualityReport, Purity) {
  io::MeshData d = io::from_mesh(make_quad_grid(3, 1));
  d.set_cell_array(cell_array("vf_a", {1, 0.5, 0}));
  d.set_cell_array(cell_array("vf_b", {0, 0.5, 1 - 1e-9}));
  d.set_cell_array(cell_array("material", {0, 1, 1}));
  QualityReport r = quality_report(d, {});
  EXPECT_TRUE(r.purity.has_material);
  EXPECT_EQ(r.purity.invalid_material_cells, 0);
  EXPECT_EQ(r.purity.mixed_cells, 1);
  ASSERT_EQ(r.purity.first_mixed.size(), 1u);
  EXPECT_EQ(r.purity.first_mixed[0], CellId(1));
  EXPECT_EQ(r.purity.fraction_arrays, (std::vector<std::string>{"vf_a", "vf_b"}));
  EXPECT_TRUE(r.purity.ok());

  d.set_cell_array(
      cell_array("material", {2, 0.5, -1}));  // beyond 2 materials, fractional, negative
  r = quality_report(d, {});
  EXPECT_EQ(r.purity.invalid_material_cells, 3);
  EXPECT_FALSE(r.purity.ok());

  io::MeshData plain = io::from_mesh(make_quad_grid(3, 1));
  plain.set_cell_array(cell_array("material", {0, 7, 3}));  // no fractions: any index >= 0
  r = quality_report(plain, {});
  EXPECT_EQ(r.purity.invalid_material_cells, 0);
  EXPECT_TRUE(quality_report(make_quad_grid(2, 2), {}).passed());
  EXPECT_FALSE(quality_report(make_quad_grid(2, 2), {}).purity.has_material);
}

TEST(QualityReport, BadInput) {
  io::MeshData empty;
  EXPECT_THROW(quality_report(empty, {}), InputError);
  io::MeshData d = two_quads();
  d.cells[3] = NodeId(99);
  EXPECT_THROW(quality_report(d, {}), InputError);
  QualityReportOptions o;
  o.bins = 0;
  EXPECT_THROW(quality_report(two_quads(), o), OptionError);
  io::MeshData m = two_quads();
  io::DataArray two = cell_array("material", {0, 0, 1, 1});
  two.n_components = 2;
  m.set_cell_array(two);
  EXPECT_THROW(quality_report(m, {}), InputError);
}

TEST(QualityReport, Json) {
  QualityReportOptions o;
  o.bins = 4;
  const auto j = nlohmann::json::parse(quality_report_json(quality_report(two_quads(), o)));
  EXPECT_EQ(j["mesh"]["cells"], 2);
  EXPECT_EQ(j["mesh"]["dim"], 2);
  EXPECT_NEAR(j["quality"]["scaled_jacobian"]["min"].get<double>(), 0.6, 1e-12);
  EXPECT_EQ(j["quality"]["histogram"]["counts"], (std::vector<int>{0, 0, 0, 2}));
  EXPECT_EQ(j["quality"]["below_threshold"]["count"], 0);
  EXPECT_TRUE(j["quality"]["passed"].get<bool>());
  EXPECT_TRUE(j["mesh_check"]["passed"].get<bool>());
  EXPECT_EQ(j["mesh_check"]["boundary_faces"], 6);
  EXPECT_TRUE(j["passed"].get<bool>());
}

}  // namespace
}  // namespace hexadapt
