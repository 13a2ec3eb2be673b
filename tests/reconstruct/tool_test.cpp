// hexadapt-reconstruct end to end: exit codes, report, output files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "hexadapt/io/mesh_file.h"
#include "reconstruct/cases.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hexadapt_reconstruct_tool_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

int run(const std::string& args) {
  const std::string cmd = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-reconstruct " + args + " 2>/dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

template <class M>
std::string write_case(const testcase::Case<M>& c, const fs::path& dir, bool with_material) {
  io::MeshData d = io::from_mesh(c.mesh);
  for (int m = 0; m < c.fractions.n_materials(); ++m) {
    io::DataArray a{"vf_" + c.fractions.names()[static_cast<std::size_t>(m)], 1, io::ScalarType::float64, {}};
    for (CellId id : id_range<CellId>(c.mesh.n_cells())) a.values.push_back(c.fractions(id, m));
    d.set_cell_array(a);
  }
  if (with_material) {
    io::DataArray a{"material", 1, io::ScalarType::int32, {}};
    for (int v : c.majority) a.values.push_back(v);
    d.set_cell_array(a);
  }
  const std::string path = (dir / (with_material ? "case.assign.vtu" : "case.vf.vtu")).string();
  io::write_mesh(d, path);
  return path;
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(ReconstructTool, WritesPixelsModelAndReport2D) {
  const fs::path dir = temp_dir("2d");
  const std::string in = write_case(testcase::five_by_five(), dir, true);
  const fs::path out = dir / "case.pixels.vtu", json = dir / "r.json", model = dir / "case.model";
  ASSERT_EQ(run(in + " -o " + out.string() + " --json " + json.string() + " --model " + model.string()), 0);
  const auto j = read_json(json);
  EXPECT_EQ(j["method"], "greedy");
  EXPECT_EQ(j["nsub"], 10);
  EXPECT_GT(j["edgecut"].get<int>(), 0);
  EXPECT_GE(j["discrepancy"].get<double>(), 0);
  EXPECT_TRUE(fs::exists(dir / "case.model.vtk"));
  const io::MeshData px = io::read_mesh(out.string());
  ASSERT_NE(px.find_cell_array("material"), nullptr);
  ASSERT_NE(px.find_cell_array("parent"), nullptr);
  EXPECT_EQ(static_cast<std::int64_t>(px.n_cells()), j["pixels"].get<std::int64_t>());
}

TEST(ReconstructTool, EveryMethodRunsAndReportsItsStatus) {
  const fs::path dir = temp_dir("methods");
  const std::string in = write_case(testcase::five_by_five(), dir, true);
  for (const std::string m : {"annealing", "graphcut", "mip"}) {
    const fs::path json = dir / (m + ".json");
    ASSERT_EQ(run(in + " -o " + (dir / (m + ".vtu")).string() + " --json " + json.string() +
                  " --method " + m + " --nsub 5 --time-limit 1 --iterations 20000"),
              0)
        << m;
    const auto j = read_json(json);
    EXPECT_EQ(j["method"], m);
    if (m == "mip") {
      const std::string st = j["status"];
      EXPECT_TRUE(st == "optimal" || st == "feasible" || st == "timed_out_no_solution") << st;
    }
  }
}

TEST(ReconstructTool, ThreeDimensionalModelGoesToOpenMesh) {
  const fs::path dir = temp_dir("3d");
  const std::string in = write_case(testcase::sphere(6, 2.2), dir, true);
  ASSERT_EQ(run(in + " -o " + (dir / "p.vtu").string() + " --model " + (dir / "m.vtk").string()), 0);
  EXPECT_TRUE(fs::exists(dir / "m.vtk"));
  EXPECT_TRUE(fs::exists(dir / "m.m0-m1.om"));
  // -q: nothing on stderr, OpenMesh's "#bytes written" included.
  const fs::path err = dir / "err.txt";
  const std::string cmd = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-reconstruct " + in +
                          " -o " + (dir / "q.vtu").string() + " --model " +
                          (dir / "q.vtk").string() + " -q 2>" + err.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(fs::file_size(err), 0u);
}

TEST(ReconstructTool, ClearErrors) {
  const fs::path dir = temp_dir("errors");
  const std::string in = write_case(testcase::five_by_five(), dir, false);
  const std::string out = " -o " + (dir / "p.vtu").string();
  EXPECT_EQ(run(in + out), 2);                 // no material array
  EXPECT_EQ(run(in + out + " --majority"), 0);
  EXPECT_EQ(run(in + out + " --majority --max-memory 1K"), 5);  // estimate above the limit
  EXPECT_EQ(run(in + out + " --majority --method simplex"), 1);
  EXPECT_EQ(run((dir / "missing.vtu").string() + out), 2);
}

}  // namespace
}  // namespace hexadapt
