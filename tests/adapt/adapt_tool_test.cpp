// End-to-end: hexadapt-adapt on a file written here, its exit codes and its output arrays.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "adapt/flow_cases.h"
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

// An assigned grid file: vf_<name> arrays and the majority `material`.
template <class M>
void write_assigned(const M& grid, const test::Shape& shape, int n_materials, int samples,
                    const fs::path& path) {
  const Fractions f = test::sample_fractions(grid, shape, n_materials, samples);
  io::MeshData data = io::from_mesh(grid);
  for (int m = 0; m < n_materials; ++m) {
    io::DataArray a{"vf_" + f.names()[static_cast<std::size_t>(m)], 1, io::ScalarType::float64, {}};
    for (CellId c : id_range<CellId>(grid.n_cells())) a.values.push_back(f(c, m));
    data.set_cell_array(a);
  }
  io::DataArray mat{"material", 1, io::ScalarType::int32, {}};
  for (CellId c : id_range<CellId>(grid.n_cells())) mat.values.push_back(f.majority(c));
  data.set_cell_array(mat);
  io::write_mesh(data, path.string());
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
  EXPECT_GT(d.n_cells(), grid.n_cells());
  ASSERT_NE(d.find_cell_array("material"), nullptr);
  ASSERT_NE(d.find_point_array("target"), nullptr);
  ASSERT_NE(d.find_point_array("distance"), nullptr);
  EXPECT_EQ(d.find_point_array("target")->n_components, 3);
  std::ifstream in(json);
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["method"], "base");
  EXPECT_EQ(report["result"]["cells"], d.n_cells());
  EXPECT_EQ(report["result"]["steps"].size(), 4u);
  EXPECT_TRUE(report["threshold_met"].get<bool>());
  fs::remove_all(dir);
}

TEST(AdaptTool, ExitCodes) {
  const fs::path dir = scratch("codes");
  const double h = 1.0 / 6;
  const QuadMesh grid = make_quad_grid(42, 18, Vec3::Zero(), Vec3(h, h, 1));
  write_assigned(grid, test::triple_point(4.0), 3, 12, dir / "in.vtu");
  const std::string in = (dir / "in.vtu").string(), out = (dir / "out.vtu").string();
  // The base method leaves cells below 0.3 here: written, but exit 3.
  EXPECT_EQ(run_tool(in + " -o " + out + " -q"), 3);
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(run_tool(in + " -o " + (dir / "g.vtu").string() + " --method guaranteed -q"), 1);
  EXPECT_EQ(run_tool(in + " -o " + in + " -q"), 1);  // refuses to overwrite its input
  EXPECT_EQ(run_tool((dir / "missing.vtu").string() + " -o " + out + " -q"), 2);
  // A grid without the material array: bad input.
  io::write_mesh(io::from_mesh(grid), (dir / "bare.vtu").string());
  EXPECT_EQ(run_tool((dir / "bare.vtu").string() + " -o " + out + " -q"), 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hexadapt
