// What the tools answer to hostile values: absurd or non-finite flow times, negative
// tolerances, files whose extent lies about their size, NaN coordinates, invalid meshes and
// unprintable tokens. Usage errors are exit 1 naming the flag, bad input exit 2 naming the file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tools/tool_fixture.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

using test::ToolRun;

class HostileValues : public test::ToolTest {};

TEST_F(HostileValues, AbsurdOrNonFiniteFlowTimesAreUsageErrors) {
  for (const char* t : {"1e9", "nan", "inf", "-inf"}) {
    const ToolRun r =
        run("generate", std::string("vortex --dims 4,4 -q --time ") + t + " -o " + path("g.vtu"));
    EXPECT_EQ(r.code, 1) << t << ": " << r.err;
    EXPECT_NE(r.err.find("flow time"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "g.vtu")) << t;
  }
  EXPECT_EQ(run("generate", "vortex --dims 4,4 -q --time 2 -o " + path("g.vtu")).code, 0);
}

TEST_F(HostileValues, NegativeOrNonFiniteTolerancesAreUsageErrorsNamingTheFlag) {
  ASSERT_EQ(run("generate", "disk --dims 4,4 -q -o " + path("in.vtu")).code, 0);
  for (const char* flag : {"--value-tolerance", "--sum-tolerance", "--zero-below"})
    for (const char* v : {"-1", "nan", "inf"}) {
      const ToolRun r =
          run("assign", path("in.vtu") + " -o " + path("o.vtu") + " " + flag + " " + v);
      EXPECT_EQ(r.code, 1) << flag << " " << v << ": " << r.err;
      EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
    }
}

TEST_F(HostileValues, AHugeExtentInATinyFileIsBadInputAtOnce) {
  write("huge.vti", R"(<VTKFile type="ImageData" version="1.0">
  <ImageData WholeExtent="0 1000 0 1000 0 1000" Origin="0 0 0" Spacing="1 1 1">
    <Piece Extent="0 1000 0 1000 0 1000"></Piece>
  </ImageData>
</VTKFile>)");
  for (const char* tool : {"measure", "assign"}) {
    const auto start = std::chrono::steady_clock::now();
    const std::string out = std::string(tool) == "assign" ? " -o " + path("o.vtu") : "";
    const ToolRun r = run(tool, path("huge.vti") + out);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.code, 2) << tool << ": " << r.err;
    EXPECT_NE(r.err.find(path("huge.vti")), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("points"), std::string::npos) << r.err;
    EXPECT_LT(seconds, 10) << tool;
  }
}

TEST_F(HostileValues, NanCoordinatesAndRepeatedNodesAreBadInputNamingTheFile) {
  const std::string head = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  const std::string cells =
      "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n9\nCELL_DATA 1\n"
      "SCALARS vf_a double 1\nLOOKUP_TABLE default\n1\n";
  write("nan.vtk", head + "POINTS 4 double\n0 0 0 1 0 0 1 nan 0 0 1 0\n" + cells);
  ToolRun r = run("assign", path("nan.vtk") + " -o " + path("o.vtu"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(path("nan.vtk")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("point 2"), std::string::npos) << r.err;
  std::string repeat = head + "POINTS 4 double\n0 0 0 1 0 0 1 1 0 0 1 0\n" + cells;
  repeat.replace(repeat.find("4 0 1 2 3"), 9, "4 0 1 1 3");
  write("repeat.vtk", repeat);
  r = run("assign", path("repeat.vtk") + " -o " + path("o.vtu"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(path("repeat.vtk")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("repeats a node"), std::string::npos) << r.err;
}

TEST_F(HostileValues, LongAndBinaryTokensAreCutAndEscaped) {
  write("junk.vtk", "# vtk DataFile Version 3.0\nt\n\x01\x02" + std::string(1 << 20, 'J') + "\n");
  const ToolRun r = run("measure", path("junk.vtk"));
  EXPECT_EQ(r.code, 2) << r.err.substr(0, 200);
  EXPECT_NE(r.err.find("'\\x01\\x02JJJ"), std::string::npos) << r.err.substr(0, 200);
  EXPECT_NE(r.err.find("...'"), std::string::npos) << r.err.substr(0, 200);
  EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 200);
}

}  // namespace
}  // namespace hexadapt
