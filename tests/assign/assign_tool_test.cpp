// End-to-end runs of hexadapt-assign: files in, files and exit codes out.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

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
  CellMaterials labels;
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
  for (int m = 0; m < 3; ++m)
    data.set_cell_array({names[m], 1, io::ScalarType::float64, {share[m], share[m], share[m]}});
  io::write_mesh(data, path("mix.vtu"));
  const ToolRun r = run(path("mix.vtu") + " -o " + path("out.vtu") + " --json " + path("r.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("material 'b' has no cell after the assignment"), std::string::npos)
      << r.err;
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

// Float32 fractions whose sums are off by 2e-3 and 5e-3 (solver error, not float32
// rounding): refused by default with the --sum-tolerance that accepts them; accepted with
// it, and the report and -v say what was decided and where it came from.
TEST_F(AssignTool, Float32FractionsReportTheToleranceDecided) {
  io::MeshData data = io::from_mesh(make_quad_grid(3, 1));
  data.set_cell_array({"vf_a", 1, io::ScalarType::float32, {0.5, 0.6, 0.5}});
  data.set_cell_array({"vf_b", 1, io::ScalarType::float32, {0.5, 0.40213, 0.50473}});
  io::write_mesh(data, path("f32.vtu"));
  const ToolRun refused = run(path("f32.vtu") + " -o " + path("out.vtu"));
  EXPECT_EQ(refused.code, 2) << refused.err;
  EXPECT_NE(refused.err.find(path("f32.vtu") + ": cell 1: fractions sum to 1.00213"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("the default for float32 data): --sum-tolerance 0.0022 would "
                             "rescale this cell, --sum-tolerance 0.0048 every cell"),
            std::string::npos)
      << refused.err;
  const ToolRun r = run(path("f32.vtu") + " -o " + path("out.vtu") + " --sum-tolerance 0.0048" +
                        " -v --json " + path("r.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("fractions stored as float32 (their rounding in a cell: at most 2.4e-07)"
                       ": sums within 0.0048 of 1 rescaled (--sum-tolerance), fractions below "
                       "1e-05 set to 0 (default); 2 cells rescaled"),
            std::string::npos)
      << r.err;
  std::ifstream in(path("r.json"));
  const auto fr = nlohmann::json::parse(in)["assign"]["fractions"];
  EXPECT_EQ(fr["stored_precision"], "float32");
  EXPECT_EQ(fr["sum_tolerance"], 0.0048);
  EXPECT_EQ(fr["sum_tolerance_given"], true);
  EXPECT_EQ(fr["zero_below"], 1e-5);
  EXPECT_EQ(fr["zero_below_given"], false);
  EXPECT_GT(fr["float32_rounding"].get<double>(), 2e-7);
  EXPECT_EQ(fr["rescaled_cells"], 2);
}

// The text format's fractions are judged by the same options: --sum-tolerance accepts a sum
// of 1.0005, which the default refuses (naming the sum as written).
TEST_F(AssignTool, TextCasesTakeTheSumTolerance) {
  std::ofstream(path("t.txt")) << "2\n2 1\n1\n2\n0 a\n2\n0 0.6\n1 1\n1 b\n1\n0 0.4005\n";
  const ToolRun refused = run(path("t.txt") + " -o " + path("out.vtu"));
  EXPECT_EQ(refused.code, 2) << refused.err;
  EXPECT_NE(refused.err.find("cell 0: fractions sum to 1.0005 (0.0005 above 1"), std::string::npos)
      << refused.err;
  const ToolRun r = run(path("t.txt") + " -o " + path("out.vtu") + " --sum-tolerance 1e-3");
  EXPECT_EQ(r.code, 0) << r.err;
}

// Material b, nowhere the majority, fills 4.2 cells: 45 % of a 2x2 block of an 8x8 grid of
// a, 30 % of a neighbour, traces elsewhere. Lost by default; with --keep-materials it takes
// the 4 cells where it is most present, the block. Reported both ways.
TEST_F(AssignTool, KeepMaterialsGivesALostMaterialTheCellsWhereItIsMostPresent) {
  io::MeshData data = io::from_mesh(make_quad_grid(8, 8));
  std::vector<double> b(64, 0.0);
  for (std::size_t c = 0; c < 5; ++c) b[c] = 0.1;
  for (std::size_t c = 48; c < 64; ++c) b[c] = 0.1;
  for (int c : {2 * 8 + 2, 2 * 8 + 3, 3 * 8 + 2, 3 * 8 + 3}) b[static_cast<std::size_t>(c)] = 0.45;
  b[10] = 0.3;
  std::vector<double> a;
  for (double x : b) a.push_back(1 - x);
  data.set_cell_array({"vf_a", 1, io::ScalarType::float64, a});
  data.set_cell_array({"vf_b", 1, io::ScalarType::float64, b});
  io::write_mesh(data, path("lost.vtu"));

  const ToolRun lost = run(path("lost.vtu") + " -o " + path("lost_out.vtu"));
  ASSERT_EQ(lost.code, 0) << lost.err;
  EXPECT_NE(lost.err.find("material 'b' has no cell"), std::string::npos) << lost.err;

  const ToolRun kept = run(path("lost.vtu") + " -o " + path("out.vtu") + " --keep-materials" +
                           " --json " + path("r.json"));
  ASSERT_EQ(kept.code, 0) << kept.err;
  EXPECT_EQ(kept.err.find("has no cell"), std::string::npos) << kept.err;
  const io::MeshData out = io::read_mesh(path("out.vtu"));
  const io::DataArray* material = out.find_cell_array("material");
  ASSERT_NE(material, nullptr);
  for (std::size_t c = 0; c < 64; ++c)
    EXPECT_EQ(material->values[c], b[c] == 0.45 ? 1 : 0) << "cell " << c;
  std::ifstream in(path("r.json"));
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["options"]["keep_materials"], true);
  EXPECT_EQ(report["assign"]["kept"], (nlohmann::json{{{"name", "b"}, {"cells", 4}}}));
  EXPECT_EQ(report["assign"]["materials"][1]["assigned_cells"], 4);
}

// One-cell islands of b in a: kept by default, given to a with --min-island 2 (and reported),
// while the 3x3 piece of b stays.
TEST_F(AssignTool, MinIslandGivesSmallPiecesToTheMaterialAroundThem) {
  io::MeshData data = io::from_mesh(make_quad_grid(8, 8));
  std::vector<double> b(64, 0.0);
  for (int y = 4; y < 7; ++y)
    for (int x = 4; x < 7; ++x) b[static_cast<std::size_t>(y * 8 + x)] = 1;
  b[1 * 8 + 1] = 0.9;
  b[1 * 8 + 5] = 0.8;
  std::vector<double> a;
  for (double x : b) a.push_back(1 - x);
  data.set_cell_array({"vf_a", 1, io::ScalarType::float64, a});
  data.set_cell_array({"vf_b", 1, io::ScalarType::float64, b});
  io::write_mesh(data, path("islands.vtu"));
  const auto b_cells = [&](const std::string& file) {
    const io::MeshData out = io::read_mesh(file);
    int n = 0;
    for (double v : out.find_cell_array("material")->values) n += v == 1;
    return n;
  };

  ASSERT_EQ(run(path("islands.vtu") + " -o " + path("plain.vtu")).code, 0);
  EXPECT_EQ(b_cells(path("plain.vtu")), 11);
  const ToolRun r = run(path("islands.vtu") + " -o " + path("out.vtu") + " --min-island 2 -v" +
                        " --json " + path("r.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(b_cells(path("out.vtu")), 9);
  EXPECT_NE(r.err.find("2 pieces smaller than 2 cells (2 cells) given to the material around"),
            std::string::npos)
      << r.err;
  std::ifstream in(path("r.json"));
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["options"]["min_island"], 2);
  EXPECT_EQ(report["assign"]["islands"]["reassigned"], 2);
  EXPECT_EQ(report["assign"]["islands"]["cells"], 2);
  EXPECT_EQ(report["assign"]["islands"]["small_pieces_final"], 0);
}

TEST_F(AssignTool, BadInputAndOptions) {
  EXPECT_EQ(run(path("case.vtu") + " -o " + path("o.vtu") + " --fractions vf_a,nope").code, 2);
  EXPECT_EQ(run(path("missing.vtu") + " -o " + path("o.vtu")).code, 2);
  EXPECT_EQ(run(path("case.vtu") + " -o " + path("o.vtu") + " --keep 0").code, 1);
  EXPECT_EQ(run(path("case.vtu") + " -o " + path("case.vtu")).code, 1);
}

}  // namespace
}  // namespace hexadapt
