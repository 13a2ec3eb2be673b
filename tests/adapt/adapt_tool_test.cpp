// End-to-end: hexadapt-adapt on a file written here, its exit codes and its output arrays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <type_traits>

#include "adapt/flow_cases.h"
#include "adapt/generated_case.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hexadapt_adapt_tool_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int run_tool(const std::string& args) {
  const std::string cmd =
      std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-adapt " + args + " 2>/dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// An assigned grid file: vf_<name> arrays and the `material` array.
template <class M>
void write_assigned(const M& grid, const Fractions& f, const IdVector<CellId, int>& material,
                    const fs::path& path) {
  io::MeshData data = io::from_mesh(grid);
  for (int m = 0; m < f.n_materials(); ++m) {
    io::DataArray a{"vf_" + f.names()[static_cast<std::size_t>(m)], 1, io::ScalarType::float64, {}};
    for (CellId c : id_range<CellId>(grid.n_cells())) a.values.push_back(f(c, m));
    data.set_cell_array(a);
  }
  io::DataArray mat{"material", 1, io::ScalarType::int32, {}};
  for (CellId c : id_range<CellId>(grid.n_cells())) mat.values.push_back(material[c]);
  data.set_cell_array(mat);
  io::write_mesh(data, path.string());
}

// The same for fractions sampled from a shape, with the majority material.
template <class M>
void write_assigned(const M& grid, const test::Shape& shape, int n_materials, int samples,
                    const fs::path& path) {
  const Fractions f = test::sample_fractions(grid, shape, n_materials, samples);
  write_assigned(grid, f, majority_materials(f), path);
}

TEST(AdaptTool, WritesTheMeshTheArraysAndTheReport) {
  const fs::path dir = scratch("disk");
  const QuadMesh grid = make_quad_grid(16, 16);
  write_assigned(
      grid, [](const Vec3& p) { return (p - Vec3(8.2, 7.9, 0)).norm() < 5.1; }, 2, 8,
      dir / "in.vtu");
  const std::string out = (dir / "out.vtu").string(), json = (dir / "out.json").string();
  ASSERT_EQ(run_tool((dir / "in.vtu").string() + " -o " + out + " --json " + json + " -q"), 0);
  const io::MeshData d = io::read_mesh(out);
  EXPECT_EQ(d.dim, 2);
  EXPECT_GE(d.n_cells(), grid.n_cells());  // cavities add cells
  ASSERT_NE(d.find_cell_array("material"), nullptr);
  ASSERT_NE(d.find_point_array("target"), nullptr);
  ASSERT_NE(d.find_point_array("distance"), nullptr);
  EXPECT_EQ(d.find_point_array("target")->n_components, 3);
  const auto names = std::find_if(d.metadata.begin(), d.metadata.end(),
                                  [](const auto& kv) { return kv.first == "hexadapt_materials"; });
  ASSERT_NE(names, d.metadata.end());  // the key of every stage's output
  EXPECT_EQ(names->second, "m0,m1");
  std::ifstream in(json);
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["method"], "guaranteed");
  ASSERT_NE(d.find_point_array("blocked"), nullptr);
  EXPECT_LE(report["result"]["dist_final"].get<double>(),
            report["result"]["dist_init"].get<double>());
  EXPECT_GE(report["result"]["min_quality"].get<double>(), 0.3);
  EXPECT_EQ(report["result"]["cells"], d.n_cells());
  // check targets pillow move cavity move-smooth reach late-cavity late-reach
  EXPECT_EQ(report["result"]["steps"].size(), 9u);
  EXPECT_LE(report["result"]["blocked_nodes"], report["result"]["reach"]["still_off"]);
  EXPECT_LE(report["result"]["late_reach"]["still_short"],
            report["result"]["late_reach"]["short_nodes"]);
  EXPECT_TRUE(report["threshold_met"].get<bool>());
  // -v says each step and where the interface nodes ended (it said nothing).
  const fs::path err = dir / "err.txt";
  const std::string verbose = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-adapt " +
                              (dir / "in.vtu").string() + " -o " + out + " -v 2>" + err.string();
  ASSERT_EQ(std::system(verbose.c_str()), 0);
  std::ifstream log(err);
  std::stringstream read;
  read << log.rdbuf();
  const std::string text = read.str();
  for (const char* step : {"step check", "step targets", "step move-smooth", "interface nodes: "})
    EXPECT_NE(text.find(step), std::string::npos) << step << " in:\n" << text;
  fs::remove_all(dir);
}

// A threshold so high that the interface nodes cannot reach their interface: the mesh meets
// it (exit 0), and stderr says how many nodes stay away and where the farthest is (it said
// nothing), as the report and the `blocked` array do.
TEST(AdaptTool, WarnsAboutNodesKeptAwayFromTheInterface) {
  const fs::path dir = scratch("blocked");
  write_assigned(
      make_quad_grid(16, 16), [](const Vec3& p) { return (p - Vec3(8.2, 7.9, 0)).norm() < 5.1; }, 2,
      8, dir / "in.vtu");
  const fs::path out = dir / "out.vtu", json = dir / "out.json", err = dir / "err.txt";
  const std::string cmd = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-adapt " +
                          (dir / "in.vtu").string() + " -o " + out.string() + " --json " +
                          json.string() + " --threshold 0.9 2>" + err.string();
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::ifstream in(json);
  const auto report = nlohmann::json::parse(in);
  const int blocked = report["result"]["blocked_nodes"];
  ASSERT_GT(blocked, 0);
  std::ifstream log(err);
  std::stringstream read;
  read << log.rdbuf();
  const std::string text = read.str();
  const std::string counted = std::to_string(blocked) + " of " +
                              std::to_string(report["result"]["interface_nodes"].get<int>()) +
                              " interface nodes";
  EXPECT_NE(text.find("warning"), std::string::npos) << text;
  EXPECT_NE(text.find(counted), std::string::npos) << counted << " in:\n" << text;
  EXPECT_NE(text.find("'blocked'"), std::string::npos) << text;
  const io::MeshData d = io::read_mesh(out.string());
  const io::DataArray* flag = d.find_point_array("blocked");
  ASSERT_NE(flag, nullptr);
  int flagged = 0;
  for (double v : flag->values) flagged += v != 0;
  EXPECT_EQ(flagged, blocked);
  fs::remove_all(dir);
}

TEST(AdaptTool, ExitCodes) {
  const fs::path dir = scratch("codes");
  QuadMesh grid;
  test::with_generated_case({"triple-point", {35, 15}, 2.0},
                            [&](const auto& g, const Fractions& f, const IdVector<CellId, int>& m) {
                              write_assigned(g, f, m, dir / "in.vtu");
                              if constexpr (std::is_same_v<std::decay_t<decltype(g)>, QuadMesh>)
                                grid = g;
                            });
  ASSERT_GT(grid.n_cells(), 0);
  const std::string in = (dir / "in.vtu").string(), out = (dir / "out.vtu").string();
  // The base method leaves cells below 0.3 here: written, but exit 3.
  EXPECT_EQ(run_tool(in + " -o " + out + " --method base -q"), 3);
  EXPECT_TRUE(fs::exists(out));
  // The guaranteed method (the default) keeps them.
  EXPECT_EQ(run_tool(in + " -o " + (dir / "g.vtu").string() + " -q"), 0);
  // Input cells below the threshold: stop with exit 3 and write nothing, unless allowed.
  const QuadMesh jittered = make_quad_grid(10, 10, test::jittered_points(10, 10, 0, 0.3, 7));
  write_assigned(
      jittered, [](const Vec3& p) { return p.x() < 4.5; }, 2, 4, dir / "jit.vtu");
  const std::string jit = (dir / "jit.vtu").string();
  const fs::path bad = dir / "bad.vtu";
  EXPECT_EQ(run_tool(jit + " -o " + bad.string() + " --threshold 0.99 -q"), 3);
  EXPECT_FALSE(fs::exists(bad));
  // Allowed, it runs: the smoothing lifts every cell of this grid above 0.9, not 0.99.
  EXPECT_EQ(run_tool(jit + " -o " + bad.string() + " --threshold 0.99 --allow-bad-input -q"), 3);
  EXPECT_TRUE(fs::exists(bad));
  EXPECT_EQ(run_tool(in + " -o " + out + " --method sculpt -q"), 1);
  EXPECT_EQ(run_tool(in + " -o " + in + " -q"), 1);  // refuses to overwrite its input
  EXPECT_EQ(run_tool((dir / "missing.vtu").string() + " -o " + out + " -q"), 2);
  // A grid without the material array: bad input.
  io::write_mesh(io::from_mesh(grid), (dir / "bare.vtu").string());
  EXPECT_EQ(run_tool((dir / "bare.vtu").string() + " -o " + out + " -q"), 2);
  fs::remove_all(dir);
}

// The size criterion: the output carries each cell's local input size, and a --min-edge the
// input grid itself breaks stops the guaranteed method with exit 3, naming the criterion,
// the cell and by how much.
TEST(AdaptTool, SizeCriterionThatCannotBeMet) {
  const fs::path dir = scratch("min_edge");
  std::vector<double> xs, ys;
  for (int i = 0; i <= 12; ++i) xs.push_back(2.0 * i);  // 2 x 1 cells: mean edge 1.5
  for (int j = 0; j <= 12; ++j) ys.push_back(1.0 * j);
  const QuadMesh grid = make_quad_grid(xs, ys);
  write_assigned(
      grid, [](const Vec3& p) { return (p - Vec3(12.3, 6.1, 0)).norm() < 4.2; }, 2, 8,
      dir / "in.vtu");
  const std::string in = (dir / "in.vtu").string(), out = (dir / "out.vtu").string();
  const std::string json = (dir / "r.json").string();
  ASSERT_EQ(run_tool(in + " -o " + out + " --json " + json + " -q"), 0);
  const io::MeshData d = io::read_mesh(out);
  const io::DataArray* local = d.find_cell_array("local_size");
  ASSERT_NE(local, nullptr);
  for (double h : local->values) EXPECT_DOUBLE_EQ(h, 1.5);
  nlohmann::json report = nlohmann::json::parse(std::ifstream(json));
  EXPECT_EQ(report["min_edge"], 0.1);
  EXPECT_EQ(report["result"]["cells_below_min_edge"], 0);
  EXPECT_GE(report["result"]["min_edge_ratio"].get<double>(), 0.1);

  // Shortest edge 1 < 0.8 x 1.5 in every input cell.
  const fs::path bad = dir / "bad.vtu";
  EXPECT_EQ(run_tool(in + " -o " + bad.string() + " --min-edge 0.8 --json " + json + " -q"), 3);
  EXPECT_FALSE(fs::exists(bad));
  report = nlohmann::json::parse(std::ifstream(json));
  EXPECT_EQ(report["bad_input_cells"].size(), static_cast<std::size_t>(grid.n_cells()));
  const auto& worst = report["result"]["failures"];
  ASSERT_EQ(worst.size(), 10u);
  EXPECT_EQ(worst[0]["failed"], nlohmann::json::array({"min_edge"}));
  EXPECT_DOUBLE_EQ(worst[0]["shortest_edge"].get<double>(), 1.0);
  EXPECT_NEAR(worst[0]["min_edge_length"].get<double>(), 1.2, 1e-12);
  EXPECT_EQ(report["exit_code"], 3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hexadapt
