// hexadapt-generate end to end: exit codes, the written file read back, same bytes for the
// same options.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "hexadapt/generate/cases.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

const std::string tool = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-generate";

int exit_code(const std::string& command) {
  const int status = std::system((command + " 2>/dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string output_of(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  return out;
}

std::string bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class GenerateTool : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hexadapt_generate_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "a");
    fs::create_directories(dir_ / "b");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(GenerateTool, ListsEveryCase) {
  const std::string list = output_of(tool + " --list");
  for (const auto& c : generate::cases())
    EXPECT_NE(list.find(c.name + " "), std::string::npos) << c.name;
}

TEST_F(GenerateTool, ExitCodes) {
  EXPECT_EQ(exit_code(tool + " no-such-case -o " + (dir_ / "x.vtu").string()), 1);
  EXPECT_EQ(exit_code(tool + " disk"), 1);                         // no output
  EXPECT_EQ(exit_code(tool + " disk --dims 4,4,4 -o x.vtu"), 1);   // disk is 2D
  EXPECT_EQ(exit_code(tool + " disk --bounds 1,2,3 -o x.vtu"), 1);
  EXPECT_EQ(exit_code(tool + " disk --dims 8,8 -o " + (dir_ / "x.unknown").string()), 1);
  EXPECT_EQ(exit_code(tool + " disk --dims 8,8 -o " + (dir_ / "none" / "x.vtu").string()), 2);
}

TEST_F(GenerateTool, WritesFractionsAndProvenance) {
  for (const char* ext : {".vtu", ".vtk"}) {
    const fs::path out = dir_ / (std::string("tp") + ext);
    ASSERT_EQ(exit_code(tool + " triple-point --dims 35,15 --extrude 2 --samples 3 -q -o " +
                        out.string() + " --json " + (dir_ / "r.json").string()),
              0);
    const io::MeshData d = io::read_mesh(out.string());
    EXPECT_EQ(d.dim, 3);
    EXPECT_EQ(d.n_cells(), 35 * 15 * 2);
    const auto* left = d.find_cell_array("vf_left");
    const auto* bottom = d.find_cell_array("vf_bottom");
    const auto* top = d.find_cell_array("vf_top");
    ASSERT_TRUE(left && bottom && top);
    for (std::size_t c = 0; c < left->values.size(); ++c)
      ASSERT_EQ(left->values[c] + bottom->values[c] + top->values[c], 1.0);
    // .vtu keeps key/value field data; legacy .vtk keeps them in its title line
    bool has_case = false;
    for (const auto& [k, v] : d.metadata)
      has_case |= (k == "hexadapt_case" && v == "triple-point") ||
                  (k == "title" && v.find("hexadapt_case=triple-point") != std::string::npos);
    EXPECT_TRUE(has_case) << ext;
    EXPECT_TRUE(fs::exists(dir_ / "r.json"));
  }
}

TEST_F(GenerateTool, SameOptionsSameBytes) {
  const std::string args = " venn --dims 24,20 --jitter 0.25 --seed 3 -q -o case.vtu";
  ASSERT_EQ(exit_code("cd " + (dir_ / "a").string() + " && " + tool + args), 0);
  ASSERT_EQ(exit_code("cd " + (dir_ / "b").string() + " && " + tool + args), 0);
  const std::string a = bytes(dir_ / "a" / "case.vtu"), b = bytes(dir_ / "b" / "case.vtu");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
}

TEST_F(GenerateTool, SameFractionsWhateverTheThreadCount) {
  const std::string args = " stir --dims 32,16 -q -o ";
  ASSERT_EQ(exit_code(tool + args + (dir_ / "a" / "c.vtu").string() + " --threads 1"), 0);
  ASSERT_EQ(exit_code(tool + args + (dir_ / "b" / "c.vtu").string() + " --threads 2"), 0);
  const auto a = io::read_mesh((dir_ / "a" / "c.vtu").string());
  const auto b = io::read_mesh((dir_ / "b" / "c.vtu").string());
  ASSERT_EQ(a.cell_data.size(), 3u);
  for (std::size_t i = 0; i < a.cell_data.size(); ++i)
    EXPECT_EQ(a.cell_data[i].values, b.cell_data[i].values);
}

}  // namespace
}  // namespace hexadapt
