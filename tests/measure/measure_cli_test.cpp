// hexadapt-measure end to end: files written by the library, the built tool run on them,
// exit codes and JSON fields checked.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/structured.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

class MeasureCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hexadapt-measure-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs the tool with these arguments; returns its exit code, stdout in `out`.
  int run(const std::string& args, std::string* out = nullptr) const {
    const std::string log = path("stdout.txt");
    const std::string cmd = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-measure " + args + " > " +
                            log + " 2> " + path("stderr.txt");
    const int status = std::system(cmd.c_str());
    if (out) *out = slurp(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  static std::string slurp(const std::string& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  nlohmann::json report() const { return nlohmann::json::parse(slurp(path("report.json"))); }

  fs::path dir_;
};

io::MeshData hex_grid_data(double bad_shift) {
  io::MeshData d = io::from_mesh(make_hex_grid(3, 3, 3));
  // Node (1,1,1) (id 21) pushed along the diagonal: the cells around it lose quality.
  d.points[21] += Vec3(bad_shift, bad_shift, bad_shift);
  return d;
}

TEST_F(MeasureCli, GoodGridPasses) {
  io::write_mesh(hex_grid_data(0), path("grid.vtu"));
  std::string out;
  ASSERT_EQ(run(path("grid.vtu") + " --json " + path("report.json"), &out), 0);
  EXPECT_NE(out.find("27 cells"), std::string::npos) << out;
  const auto j = report();
  EXPECT_EQ(j["tool"], "hexadapt-measure");
  EXPECT_EQ(j["mesh"]["cells"], 27);
  EXPECT_EQ(j["mesh"]["nodes"], 64);
  EXPECT_EQ(j["mesh"]["dim"], 3);
  EXPECT_DOUBLE_EQ(j["quality"]["scaled_jacobian"]["min"].get<double>(), 1.0);
  EXPECT_EQ(j["quality"]["histogram"]["counts"].size(), 20u);
  EXPECT_EQ(j["quality"]["histogram"]["counts"][19], 27);
  EXPECT_TRUE(j["mesh_check"]["passed"].get<bool>());
  EXPECT_TRUE(j["passed"].get<bool>());
  EXPECT_EQ(j["exit_code"], 0);
}

TEST_F(MeasureCli, ThresholdDecidesTheExitCode) {
  const io::MeshData d = hex_grid_data(0.3);
  io::write_mesh(d, path("bent.vtk"));
  double worst = 1;
  for (CellId c : id_range<CellId>(d.n_cells())) {
    std::array<Vec3, 8> p;
    for (std::size_t k = 0; k < 8; ++k) p[k] = d.points[d.cells[c.idx() * 8 + k].idx()];
    worst = std::min(worst, hex_scaled_jacobian(p));
  }
  ASSERT_GT(worst, 0.05);
  ASSERT_LT(worst, 0.3);
  EXPECT_EQ(run(path("bent.vtk") + " -q --bins 8 --json " + path("report.json")), 3);
  auto j = report();
  EXPECT_NEAR(j["quality"]["scaled_jacobian"]["min"].get<double>(), worst, 1e-12);
  EXPECT_GT(j["quality"]["below_threshold"]["count"].get<int>(), 0);
  EXPECT_FALSE(j["quality"]["passed"].get<bool>());
  EXPECT_TRUE(j["mesh_check"]["passed"].get<bool>());
  EXPECT_EQ(j["quality"]["histogram"]["counts"].size(), 8u);
  EXPECT_EQ(run(path("bent.vtk") + " --threshold 0.05 --json " + path("report.json")), 0);
  EXPECT_EQ(report()["quality"]["below_threshold"]["count"], 0);
}

TEST_F(MeasureCli, HangingNodeFailsTheCheck) {
  io::MeshData d;
  d.dim = 2;
  d.points = {{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0},
              {1, 1, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}};
  for (int n : {0, 1, 2, 3, 1, 5, 6, 4, 4, 6, 7, 2}) d.cells.push_back(NodeId(n));
  io::write_mesh(d, path("t.vtu"));
  EXPECT_EQ(run(path("t.vtu") + " --json " + path("report.json")), 3);
  const auto j = report();
  EXPECT_EQ(j["mesh_check"]["hanging_nodes"], 1);
  EXPECT_EQ(j["mesh_check"]["first"]["hanging_nodes"][0]["node"], 4);
  EXPECT_TRUE(j["quality"]["passed"].get<bool>());
  EXPECT_FALSE(j["passed"].get<bool>());
}

TEST_F(MeasureCli, FaceSharedByThreeCellsIsAFailedCheck) {
  io::MeshData d = io::from_mesh(make_hex_grid(1, 1, 2));
  for (int v = 0; v < 4; ++v)
    d.points.push_back(d.points[d.cells[12 + static_cast<std::size_t>(v)].idx()] + Vec3(0, 0, 5));
  for (int v = 0; v < 8; ++v)
    d.cells.push_back(v < 4 ? d.cells[8 + static_cast<std::size_t>(v)] : NodeId(12 + v - 4));
  io::write_mesh(d, path("three.vtu"));
  EXPECT_EQ(run(path("three.vtu") + " --json " + path("report.json")), 3);
  const auto j = report();
  EXPECT_FALSE(j["mesh_check"]["representable"].get<bool>());
  EXPECT_EQ(j["mesh"]["cells"], 3);
}

TEST_F(MeasureCli, QualityFieldHoldsThePerCellValues) {
  const io::MeshData d = hex_grid_data(0.3);
  io::write_mesh(d, path("in.vtu"));
  EXPECT_EQ(run(path("in.vtu") + " -q --threshold 0 --quality-field " + path("q.vtu")), 0);
  const io::MeshData q = io::read_mesh(path("q.vtu"));
  const io::DataArray* sj = q.find_cell_array("scaled_jacobian");
  ASSERT_NE(sj, nullptr);
  ASSERT_NE(q.find_cell_array("shape"), nullptr);
  ASSERT_EQ(sj->values.size(), 27u);
  for (CellId c : id_range<CellId>(d.n_cells())) {
    std::array<Vec3, 8> p;
    for (std::size_t k = 0; k < 8; ++k) p[k] = d.points[d.cells[c.idx() * 8 + k].idx()];
    EXPECT_DOUBLE_EQ(sj->values[c.idx()], hex_scaled_jacobian(p)) << c.value();
  }
  // Never over the input.
  EXPECT_EQ(run(path("in.vtu") + " --quality-field " + path("in.vtu")), 1);
}

TEST_F(MeasureCli, PurityOfAMaterialArray) {
  io::MeshData d = io::from_mesh(make_quad_grid(2, 2));
  io::DataArray m;
  m.name = "material";
  m.type = io::ScalarType::int32;
  m.values = {0, 1, 1, 0};
  d.set_cell_array(m);
  io::write_mesh(d, path("m.vtu"));
  EXPECT_EQ(run(path("m.vtu") + " --json " + path("report.json")), 0);
  const auto j = report();
  EXPECT_TRUE(j["purity"]["material_array"].get<bool>());
  EXPECT_EQ(j["purity"]["invalid_material_cells"], 0);
}

TEST_F(MeasureCli, BadInputAndUsage) {
  EXPECT_EQ(run(path("missing.vtu")), 2);
  { std::ofstream(path("garbage.vtu")) << "this is not a VTK file\n"; }
  EXPECT_EQ(run(path("garbage.vtu")), 2);
  io::write_mesh(hex_grid_data(0), path("grid.vtu"));
  EXPECT_EQ(run(path("grid.vtu") + " --bins 0"), 1);
  EXPECT_EQ(run(path("grid.vtu") + " --no-such-option"), 1);
  EXPECT_EQ(run(""), 1);
}

TEST_F(MeasureCli, HelpDocumentsEveryOption) {
  std::string out;
  ASSERT_EQ(run("--help", &out), 0);
  for (const char* opt :
       {"--threshold", "--bins", "--quality-field", "--json", "--threads", "-q", "-v", "--list",
        "--duplicate-tolerance", "--conformity-tolerance", "--material-array", "--plane",
        "--reference", "--discrepancy-field", "--target-array", "--min-edge", "--max-volume-error"})
    EXPECT_NE(out.find(opt), std::string::npos) << opt;
}

// A 4x4x1 reference grid whose interface x = 1.5 splits column 1 in halves (material
// volumes: left 6, right 10), and a 2x2x1 output mesh (cells of size 2) with material 0 left
// of x = 2 (volumes 8 and 8).
io::MeshData two_material_reference() {
  io::MeshData ref = io::from_mesh(make_hex_grid(4, 4, 1));
  io::DataArray left{"vf_left", 1, io::ScalarType::float64, {}}, right = left;
  right.name = "vf_right";
  for (index_t c = 0; c < 16; ++c) {
    const double x0 = static_cast<double>(c % 4);
    const double f = x0 < 1 ? 1.0 : x0 < 2 ? 0.5 : 0.0;
    left.values.push_back(f);
    right.values.push_back(1 - f);
  }
  ref.set_cell_array(left);
  ref.set_cell_array(right);
  return ref;
}

io::MeshData two_material_mesh() {
  io::MeshData mesh = io::from_mesh(make_hex_grid(2, 2, 1, Vec3::Zero(), Vec3(2, 2, 1)));
  mesh.set_cell_array({"material", 1, io::ScalarType::int32, {0, 1, 0, 1}});
  return mesh;
}

// The column of reference cells x in [1, 2) is off by 2 * 0.5 per cell, the total is
// 4 * 1 = 4 of a volume of 16.
TEST_F(MeasureCli, DiscrepancyAgainstReference) {
  io::write_mesh(two_material_reference(), path("ref.vtu"));
  io::MeshData mesh = two_material_mesh();
  io::DataArray target{"target", 3, io::ScalarType::float64, {}};
  for (const Vec3& p : mesh.points)
    for (double v : {p.x() + 0.5, p.y(), p.z()}) target.values.push_back(v);
  mesh.set_point_array(target);
  io::write_mesh(mesh, path("mesh.vtu"));
  std::string out;
  ASSERT_EQ(run(path("mesh.vtu") + " --reference " + path("ref.vtu") + " --discrepancy-field " +
                    path("d.vtu") + " --json " + path("report.json"),
                &out),
            0)
      << out << slurp(path("stderr.txt"));
  const auto j = report();
  EXPECT_NEAR(j["discrepancy"]["total"].get<double>(), 4.0, 1e-12);
  EXPECT_NEAR(j["discrepancy"]["relative"].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(j["discrepancy"]["max_cell"]["value"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(j["discrepancy"]["max_cell"]["cell"].get<int>() % 4, 1);  // ties up to rounding
  EXPECT_EQ(j["discrepancy"]["materials"][0]["name"], "left");
  EXPECT_NEAR(j["discrepancy"]["materials"][0]["input"].get<double>(), 6.0, 1e-12);
  EXPECT_NEAR(j["discrepancy"]["materials"][0]["output"].get<double>(), 8.0, 1e-12);
  EXPECT_NEAR(j["distances"]["dist"].get<double>(), 0.5 * 18, 1e-12);
  EXPECT_NEAR(j["distances"]["max"].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(j["distances"]["nodes"], 18);
  const io::MeshData field = io::read_mesh(path("d.vtu"));
  const io::DataArray* d = field.find_cell_array("discrepancy");
  ASSERT_NE(d, nullptr);
  for (index_t c = 0; c < 16; ++c)
    EXPECT_NEAR(d->values[static_cast<std::size_t>(c)], c % 4 == 1 ? 1.0 : 0.0, 1e-12) << c;
  // A material index with no fraction array, and a field without a reference.
  mesh.set_cell_array({"material", 1, io::ScalarType::int32, {0, 2, 0, 1}});
  io::write_mesh(mesh, path("bad.vtu"));
  EXPECT_EQ(run(path("bad.vtu") + " --reference " + path("ref.vtu")), 2);
  EXPECT_NE(slurp(path("stderr.txt")).find("bad.vtu"), std::string::npos);
  EXPECT_EQ(run(path("mesh.vtu") + " --discrepancy-field " + path("e.vtu")), 1);
}

// The reference is read as every stage reads an input grid (io::to_assigned_grid): a cell
// that repeats a node is bad input, named with the reference's file and the cell.
TEST_F(MeasureCli, ReferenceIsReadAsAnInputGrid) {
  io::MeshData ref = two_material_reference();
  ref.cells[5 * 8 + 1] = ref.cells[5 * 8];
  io::write_mesh(ref, path("ref.vtu"));
  io::write_mesh(two_material_mesh(), path("mesh.vtu"));
  EXPECT_EQ(run(path("mesh.vtu") + " --reference " + path("ref.vtu")), 2);
  const std::string err = slurp(path("stderr.txt"));
  EXPECT_NE(err.find(path("ref.vtu")), std::string::npos) << err;
  EXPECT_NE(err.find("cell 5"), std::string::npos) << err;
}

// Volume errors: left (8 - 6) / 6 = 1/3, right (8 - 10) / 10 = -1/5.
TEST_F(MeasureCli, MaxVolumeErrorDecidesTheExitCode) {
  io::write_mesh(two_material_reference(), path("ref.vtu"));
  io::write_mesh(two_material_mesh(), path("mesh.vtu"));
  const std::string args =
      path("mesh.vtu") + " -q --reference " + path("ref.vtu") + " --json " + path("report.json");
  ASSERT_EQ(run(args), 0) << slurp(path("stderr.txt"));
  auto j = report();
  EXPECT_NEAR(j["discrepancy"]["materials"][0]["volume_error"].get<double>(), 1.0 / 3, 1e-12);
  EXPECT_NEAR(j["discrepancy"]["materials"][1]["volume_error"].get<double>(), -0.2, 1e-12);
  EXPECT_EQ(j["discrepancy"]["worst_volume_error"]["name"], "left");
  EXPECT_NEAR(j["discrepancy"]["worst_volume_error"]["value"].get<double>(), 1.0 / 3, 1e-12);
  EXPECT_TRUE(j["discrepancy"]["max_volume_error"].is_null());
  EXPECT_TRUE(j["discrepancy"]["passed"].get<bool>());
  EXPECT_EQ(run(args + " --max-volume-error 0.34"), 0);
  EXPECT_TRUE(report()["passed"].get<bool>());
  EXPECT_EQ(run(args + " --max-volume-error 0.3"), 3);
  j = report();
  EXPECT_FALSE(j["passed"].get<bool>());
  EXPECT_FALSE(j["discrepancy"]["passed"].get<bool>());
  EXPECT_DOUBLE_EQ(j["discrepancy"]["max_volume_error"].get<double>(), 0.3);
  EXPECT_TRUE(j["quality"]["passed"].get<bool>());
  EXPECT_EQ(j["exit_code"], 3);
  // The input volumes come from the reference: no bound without it.
  EXPECT_EQ(run(path("mesh.vtu") + " --max-volume-error 0.3"), 1);
}

// 2x2 unit squares whose node (1, 0) slid to (0.05, 0): cell 0 has an edge of 0.05 local
// sizes, below the default --min-edge 0.1.
TEST_F(MeasureCli, SliverFailsTheMinEdge) {
  io::MeshData d = io::from_mesh(make_quad_grid(2, 2));
  d.points[1] = Vec3(0.05, 0, 0);
  d.set_cell_array({"material", 1, io::ScalarType::int32, {0, 0, 0, 0}});
  io::write_mesh(d, path("plain.vtu"));
  d.set_cell_array({"local_size", 1, io::ScalarType::float64, {1, 1, 1, 1}});
  io::write_mesh(d, path("sliver.vtu"));
  std::string out;
  EXPECT_EQ(run(path("sliver.vtu") + " --json " + path("report.json"), &out), 3);
  EXPECT_NE(out.find("min edge 0.1 x local size"), std::string::npos) << out;
  auto j = report();
  EXPECT_FALSE(j["passed"].get<bool>());
  EXPECT_TRUE(j["quality"]["passed"].get<bool>());
  EXPECT_FALSE(j["size"]["passed"].get<bool>());
  EXPECT_EQ(j["size"]["local_size"], "array");
  EXPECT_EQ(j["size"]["below_min_edge"]["count"], 1);
  EXPECT_EQ(j["size"]["below_min_edge"]["first"][0]["cell"], 0);
  EXPECT_NEAR(j["size"]["relative_edge"]["min"].get<double>(), 0.05, 1e-12);
  EXPECT_EQ(run(path("sliver.vtu") + " --min-edge 0 --json " + path("report.json")), 0);
  j = report();
  EXPECT_TRUE(j["passed"].get<bool>());
  EXPECT_FALSE(j["size"]["checked"].get<bool>());
  EXPECT_EQ(run(path("sliver.vtu") + " -q --min-edge 0.04"), 0);
  // No local size: measured without it, not checked, not failed.
  EXPECT_EQ(run(path("plain.vtu") + " --json " + path("report.json"), &out), 0);
  EXPECT_NE(out.find("no local_size array and no reference grid"), std::string::npos) << out;
  EXPECT_EQ(report()["size"]["not_checked"], "no local_size array and no reference grid");
  // The reference grid gives the local size: unit squares, the same verdict.
  io::MeshData ref = io::from_mesh(make_quad_grid(2, 2));
  ref.set_cell_array({"vf_a", 1, io::ScalarType::float64, {1, 1, 1, 1}});
  io::write_mesh(ref, path("ref.vtu"));
  EXPECT_EQ(
      run(path("plain.vtu") + " --reference " + path("ref.vtu") + " --json " + path("report.json")),
      3);
  j = report();
  EXPECT_EQ(j["size"]["local_size"], "reference");
  EXPECT_EQ(j["size"]["below_min_edge"]["count"], 1);
  EXPECT_NEAR(j["size"]["time_step_ratio"].get<double>(), 0.525 / std::sqrt(0.95 * 0.95 + 1),
              1e-12);
  EXPECT_EQ(run(path("sliver.vtu") + " --min-edge -1"), 1);
}

}  // namespace
}  // namespace hexadapt
