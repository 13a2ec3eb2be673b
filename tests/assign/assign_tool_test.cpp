// End-to-end runs of hexadapt-assign: files in, files and exit codes out.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "brute_force_manifold.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

struct ToolRun {
  int code = -1;
  std::string err;
};

class AssignTool : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hexadapt_assign_tool_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    write_livelock_case(path("case.vtu"));
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  ToolRun run(const std::string& args) const {
    const std::string err = path("stderr.txt");
    const std::string cmd =
        std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-assign " + args + " 2> " + err;
    const int status = std::system(cmd.c_str());
    ToolRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err);
    std::stringstream s;
    s << in.rdbuf();
    r.err = s.str();
    return r;
  }

  /// The 4x4 case of the correction tests where node (2,1) is treated twice.
  static void write_livelock_case(const std::string& file) {
    const double w[16][3] = {{7, 3, 0}, {2, 1, 0},  {2, 5, 8}, {1, 9, 6}, {5, 2, 2}, {1, 4, 0},
                             {9, 5, 0}, {9, 9, 2},  {7, 5, 4}, {9, 4, 0}, {1, 0, 0}, {1, 1, 1},
                             {8, 5, 4}, {5, 7, 10}, {0, 1, 0}, {8, 9, 4}};
    io::MeshData data = io::from_mesh(make_quad_grid(4, 4));
    const char* names[3] = {"vf_a", "vf_b", "vf_c"};
    for (int m = 0; m < 3; ++m) {
      io::DataArray a;
      a.name = names[m];
      for (const auto& c : w) a.values.push_back(c[m] / (c[0] + c[1] + c[2]));
      data.set_cell_array(a);
    }
    io::write_mesh(data, file);
  }

  fs::path dir_;
};

TEST_F(AssignTool, WritesBothAssignmentsAndAReport) {
  const ToolRun r =
      run(path("case.vtu") + " -o " + path("out.vtu") + " --json " + path("report.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  const io::MeshData out = io::read_mesh(path("out.vtu"));
  const io::DataArray* material = out.find_cell_array("material");
  const io::DataArray* majority = out.find_cell_array("majority");
  ASSERT_TRUE(material && majority);
  EXPECT_EQ(material->type, io::ScalarType::int32);
  EXPECT_TRUE(out.find_cell_array("vf_a") && out.find_cell_array("vf_c"));
  assign::Labels labels;
  for (double v : material->values) labels.push_back(static_cast<int>(v));
  const auto mesh = std::get<QuadMesh>(io::to_mesh(out));
  EXPECT_EQ(test::count_non_manifold(mesh, labels, 3), 0);
  EXPECT_EQ(majority->values[1], 0);  // cell 1 is 2/3 of material a
  EXPECT_NE(material->values, majority->values);

  std::ifstream in(path("report.json"));
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["assign"]["non_manifold_nodes_initial"], 1);
  EXPECT_EQ(report["assign"]["solved"], true);
  EXPECT_GT(report["assign"]["cells_changed"].get<int>(), 0);
  EXPECT_GT(report["assign"]["cost_added"].get<double>(), 0);
  EXPECT_TRUE(report["times"].contains("correct"));
  EXPECT_EQ(report["materials"], (nlohmann::json{"a", "b", "c"}));
}

// Three cells of a 0.6 / 0.1 / 0.3 mix: b and c are nowhere the majority and get no cell.
// The assignment is right to do so, but they are then lost to every later stage: the tool
// says so on stderr and gives each material's input and assigned volume in the report.
TEST_F(AssignTool, AMaterialThatIsNowhereTheMajorityIsReportedLost) {
  io::MeshData data = io::from_mesh(make_quad_grid(3, 1));
  const char* names[3] = {"vf_a", "vf_b", "vf_c"};
  const double share[3] = {0.6, 0.1, 0.3};
  for (int m = 0; m < 3; ++m) data.set_cell_array({names[m], 1, io::ScalarType::float64,
                                                   {share[m], share[m], share[m]}});
  io::write_mesh(data, path("mix.vtu"));
  const ToolRun r = run(path("mix.vtu") + " -o " + path("out.vtu") + " --json " + path("r.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("material 'b' has no cell after the assignment"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("material 'c' has no cell"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(30 % of the domain"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("material 'a'"), std::string::npos) << r.err;
  std::ifstream in(path("r.json"));
  const auto materials = nlohmann::json::parse(in)["assign"]["materials"];
  ASSERT_EQ(materials.size(), 3u);
  EXPECT_EQ(materials[0]["assigned_cells"], 3);
  EXPECT_DOUBLE_EQ(materials[0]["assigned_volume"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(materials[0]["input_volume"].get<double>(), 1.8);
  EXPECT_EQ(materials[2]["name"], "c");
  EXPECT_EQ(materials[2]["assigned_cells"], 0);
  EXPECT_NEAR(materials[2]["input_share"].get<double>(), 0.3, 1e-12);
}

TEST_F(AssignTool, RunningOutOfConfigurationsExitsThreeAndWritesThePartialResult) {
  const ToolRun r = run(path("case.vtu") + " -o " + path("out.vtu") + " --keep 1 --paper-order" +
                        " --partial " + path("partial.vtu") + " --json " + path("report.json"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("node 7 (2, 1, 0)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("materials a, b, c"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--keep"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.vtu")));
  ASSERT_TRUE(fs::exists(path("partial.vtu")));
  EXPECT_TRUE(io::read_mesh(path("partial.vtu")).find_cell_array("material"));
  std::ifstream in(path("report.json"));
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["assign"]["failure"]["node"], 7);
}

TEST_F(AssignTool, BadInputAndOptions) {
  EXPECT_EQ(run(path("case.vtu") + " -o " + path("o.vtu") + " --fractions vf_a,nope").code, 2);
  EXPECT_EQ(run(path("missing.vtu") + " -o " + path("o.vtu")).code, 2);
  EXPECT_EQ(run(path("case.vtu") + " -o " + path("o.vtu") + " --keep 0").code, 1);
  EXPECT_EQ(run(path("case.vtu") + " -o " + path("case.vtu")).code, 1);
}

}  // namespace
}  // namespace hexadapt
