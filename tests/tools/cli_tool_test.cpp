// Command-line conventions every tool shares: --version, usage errors for outputs a tool
// cannot write, and listings a person can read.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/structured.h"
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

// Help lists a choice by its words: a CLI11 transformer printed
// "ENUM:value in {auto->0,xy->1,...} OR {0,1,...}", the enum's numbers included.
TEST_F(CliTool, EveryToolsHelpNamesChoicesByTheirWords) {
  for (const char* tool : {"generate", "assign", "reconstruct", "adapt", "measure", "render"}) {
    const ToolRun r = run(tool, "--help");
    EXPECT_EQ(r.code, 0) << tool << ": " << r.err;
    for (const char* leak : {"ENUM", "->", "value in {"})
      EXPECT_EQ(r.out.find(leak), std::string::npos) << tool << " --help shows " << leak;
  }
  EXPECT_NE(run("render", "--help").out.find("--plane TEXT:{auto,xy,yz,xz}=auto"),
            std::string::npos);
  EXPECT_NE(run("adapt", "--help").out.find("--volume-offset TEXT:{automatic,on,off}=automatic"),
            std::string::npos);
}

// The library names an option by its Options field in braces; each tool shows its own flag
// there, in errors and warnings alike, and leaves other braces in a message alone.
TEST_F(CliTool, LibraryMessagesShowTheToolsFlags) {
  const ToolRun bad = run("generate", "asteroid --dims 8,8,8 --extrude 2 -o " + path("a.vtu"));
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("error: --extrude sweeps a 2D case"), std::string::npos) << bad.err;
  const ToolRun warned = run("generate", "asteroid --dims 4,4,4 --time 1 -o " + path("b.vtu"));
  EXPECT_EQ(warned.code, 0) << warned.err;
  EXPECT_NE(warned.err.find("has no flow: --time is ignored"), std::string::npos) << warned.err;
  const ToolRun braces = run("generate", "disk --dims 4,4 -o " + path("{nsub}.vtu") + " -q");
  EXPECT_EQ(braces.code, 0) << braces.err;
  EXPECT_TRUE(std::filesystem::exists(path("{nsub}.vtu")));
  for (const ToolRun* r : {&bad, &warned}) EXPECT_EQ(r->err.find('{'), std::string::npos) << r->err;
}

// A number flag out of range says which bound it breaks (CLI11's own check printed a
// 309-digit upper bound).
TEST_F(CliTool, NumberFlagsOutOfRangeSayTheirBound) {
  const ToolRun steps = run("adapt", "in.vtu -o " + path("m.vtu") + " --steps 0");
  EXPECT_EQ(steps.code, 1);
  EXPECT_NE(steps.err.find("--steps: must be > 0, got 0"), std::string::npos) << steps.err;
  const ToolRun loops = run("adapt", "in.vtu -o " + path("m.vtu") + " --max-loops -1");
  EXPECT_EQ(loops.code, 1);
  EXPECT_NE(loops.err.find("--max-loops: must be >= 0, got -1"), std::string::npos) << loops.err;
  for (const ToolRun* r : {&steps, &loops})
    EXPECT_EQ(r->err.find("17976931348623157"), std::string::npos) << r->err;
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

// Fraction arrays named as a real solver names them go through every stage, the 3D model
// included: --fractions took the comma for a separator, and the model's title line split the
// names at their spaces (adapt then refused the model as another grid's).
TEST_F(CliTool, MaterialNamesWithSpacesAndCommasGoThroughEveryStage) {
  io::MeshData d = io::from_mesh(make_hex_grid(6, 6, 6));
  io::DataArray body{"Volume Fraction for Body, Nose", 1, io::ScalarType::float64, {}};
  io::DataArray air{"Volume Fraction for Air", 1, io::ScalarType::float64, {}};
  for (index_t c = 0; c < d.n_cells(); ++c) {
    const bool inside = c % 6 >= 2 && c % 6 < 4 && c / 6 % 6 >= 2 && c / 6 % 6 < 4 && c / 36 >= 2 && c / 36 < 4;
    body.values.push_back(inside ? 1.0 : 0.0);
    air.values.push_back(inside ? 0.0 : 1.0);
  }
  d.set_cell_array(body);
  d.set_cell_array(air);
  io::write_mesh(d, path("in.vtu"));
  const std::string arrays = "--fractions 'Volume Fraction for Body, Nose' 'Volume Fraction for Air'";
  ToolRun r = run("assign", "-o " + path("a.vtu") + " " + arrays + " -- " + path("in.vtu"));
  ASSERT_EQ(r.code, 0) << r.err;
  r = run("reconstruct", path("a.vtu") + " -o " + path("p.vtu") + " --model " + path("m.vtk") +
                             " -q " + arrays);
  ASSERT_EQ(r.code, 0) << r.err;
  r = run("adapt", path("a.vtu") + " -o " + path("o.vtu") + " --model " + path("m.vtk") +
                       " --correction -q " + arrays);
  EXPECT_EQ(r.code, 0) << r.err;
}

std::string last_command(const io::MeshData& d) {
  std::string command;
  for (const auto& [key, value] : d.metadata)
    if (key == "hexadapt_command") command = value;
  return command;
}

TEST_F(CliTool, RecordedCommandIsExactAndCanBePastedBack) {
  std::filesystem::create_directories(path("out dir"));
  // An output name with a space and a quote: typed in quotes, recorded in quotes.
  const std::string typed =
      "disk --dims 4,3 -o '" + path("out dir") + "/it'\\''s.EXT' --json " + path("r.json") + " -q";
  const auto with = [](std::string s, const std::string& ext) {
    return s.replace(s.find("EXT"), 3, ext);
  };
  for (const std::string ext : {"vtu", "vtk"}) {
    ToolRun r = run("generate", with(typed, ext));
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string expected = "hexadapt-generate " + with(typed, ext);
    const std::string file = path("out dir") + "/it's." + ext;
    EXPECT_EQ(nlohmann::json::parse(file_content(path("r.json")))["command"], expected);
    EXPECT_EQ(last_command(io::read_mesh(file)), expected);
    // Pasted into a shell (run before the tool's --version), it makes the same file again.
    const std::string first = file_content(file);
    std::filesystem::remove(file);
    write("again.sh", expected + "\n");
    r = run("generate", "--version",
            "PATH=" + std::string(HEXADAPT_TOOLS_DIR) + ":$PATH sh " + path("again.sh") + " && ");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(file_content(file), first) << ext;
  }
}

}  // namespace
}  // namespace hexadapt::test
