// Command-line conventions every tool shares: --version, usage errors for outputs a tool
// cannot write, and listings a person can read.
#include <sstream>
#include <string>
#include <vector>

#include "tools/tool_fixture.h"

namespace hexadapt::test {
namespace {

class CliTool : public ToolTest {};

TEST_F(CliTool, EveryToolPrintsItsVersion) {
  for (const char* tool : {"generate", "assign", "reconstruct", "adapt", "measure", "render"}) {
    const ToolRun r = run(tool, "--version");
    EXPECT_EQ(r.code, 0) << tool << ": " << r.err;
    EXPECT_EQ(r.out, std::string("hexadapt ") + HEXADAPT_VERSION + "\n") << tool;
  }
}

// render draws PNG only: -o x.jpg or x.svg used to get PNG bytes under that name.
TEST_F(CliTool, RenderRefusesAPictureFormatItDoesNotWrite) {
  for (const char* name : {"x.jpg", "x.svg", "x"}) {
    const ToolRun r = run("render", "in.vtu -o " + path(name));
    EXPECT_EQ(r.code, 1) << name;
    EXPECT_NE(r.err.find("PNG"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path(name))) << name;
  }
}

// A header, then one case a line, every column starting at the same place.
TEST_F(CliTool, GenerateListsItsCasesInColumnsUnderAHeader) {
  const ToolRun r = run("generate", "--list");
  ASSERT_EQ(r.code, 0);
  std::istringstream in(r.out);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GT(lines.size(), 5u);
  EXPECT_EQ(lines[0].rfind("case ", 0), 0u) << lines[0];
  for (const char* column : {"dims", "flow", "materials", "summary"}) {
    const std::size_t at = lines[0].find(column);
    ASSERT_NE(at, std::string::npos) << column;
    for (std::size_t i = 1; i < lines.size(); ++i) {
      ASSERT_GT(lines[i].size(), at) << lines[i];
      EXPECT_EQ(lines[i][at - 1], ' ') << column << " in: " << lines[i];
      EXPECT_NE(lines[i][at], ' ') << column << " in: " << lines[i];
    }
  }
}

}  // namespace
}  // namespace hexadapt::test
