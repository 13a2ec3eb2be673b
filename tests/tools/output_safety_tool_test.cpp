// What the tools do with hostile file arguments: outputs that name inputs or each other,
// symlinks, `--json -`, outputs in missing directories, directories, FIFOs and devices as
// inputs, and absurd thread counts. Nothing may be lost, and no answer is exit 4.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tools/tool_fixture.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

using test::ToolRun;

class OutputSafety : public test::ToolTest {
 protected:
  void SetUp() override {
    ToolTest::SetUp();
    ASSERT_EQ(run("generate", "disk --dims 8,8 -q -o " + path("in.vtu")).code, 0);
    input_ = test::file_content(dir_ / "in.vtu");
  }
  bool input_intact() const { return test::file_content(dir_ / "in.vtu") == input_; }

  std::string input_;
};

TEST_F(OutputSafety, JsonNamingTheInputIsAUsageErrorAndTheInputSurvives) {
  for (const char* tool : {"assign", "measure"}) {
    const std::string out = std::string(tool) == "assign" ? " -o " + path("o.vtu") : "";
    const ToolRun r = run(tool, path("in.vtu") + out + " --json " + path("in.vtu"));
    EXPECT_EQ(r.code, 1) << tool;
    EXPECT_NE(r.err.find("--json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("input"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(path("in.vtu")), std::string::npos) << r.err;
    EXPECT_TRUE(input_intact()) << tool;
    EXPECT_FALSE(fs::exists(dir_ / "o.vtu"));
  }
}

TEST_F(OutputSafety, TwoOutputsNamingOneFileAreAUsageError) {
  std::ofstream(dir_ / "o.vtu") << "keep";
  const ToolRun r =
      run("assign", path("in.vtu") + " -o " + path("o.vtu") + " --json " + path("./o.vtu"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("-o"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--json"), std::string::npos) << r.err;
  EXPECT_EQ(test::file_content(dir_ / "o.vtu"), "keep");
  // Also when the file does not exist yet, and through a symlink to the input.
  EXPECT_EQ(
      run("assign", path("in.vtu") + " -o " + path("new.vtu") + " --partial " + path("new.vtu"))
          .code,
      1);
  fs::create_symlink("in.vtu", dir_ / "alias.vtu");
  EXPECT_EQ(run("assign", path("in.vtu") + " -o " + path("alias.vtu")).code, 1);
  EXPECT_TRUE(input_intact());
}

TEST_F(OutputSafety, OutputsGoThroughSymlinksAndJsonDashIsStandardOutput) {
  fs::create_directories(dir_ / "real");
  std::ofstream(dir_ / "real" / "out.vtu") << "old";
  fs::create_symlink("real/out.vtu", dir_ / "out.vtu");
  const ToolRun r = run("assign", path("in.vtu") + " -q -o " + path("out.vtu") + " --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "out.vtu"));
  EXPECT_NE(test::file_content(dir_ / "real" / "out.vtu"), "old");
  EXPECT_FALSE(fs::exists(dir_ / "-"));
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["tool"], "hexadapt-assign");
  // /dev/stdout is written, not replaced, whatever standard output is (here a file).
  const ToolRun s =
      run("assign", path("in.vtu") + " -q -o " + path("out.vtu") + " --json /dev/stdout");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(nlohmann::json::parse(s.out)["tool"], "hexadapt-assign");
}

TEST_F(OutputSafety, AnOutputInAMissingDirectoryStopsTheRunBeforeAnyOutput) {
  const ToolRun r =
      run("assign", path("in.vtu") + " -o " + path("out.vtu") + " --json " + path("nodir/r.json"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nodir"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.vtu"));
  EXPECT_EQ(
      run("generate", "disk --dims 8,8 -o " + path("g.vtu") + " --json " + path("nodir/g.json"))
          .code,
      2);
  EXPECT_FALSE(fs::exists(dir_ / "g.vtu"));
  for (const auto& e : fs::directory_iterator(dir_))  // no temporary file left behind
    EXPECT_NE(e.path().extension(), ".tmp") << e.path();
}

// A mesh output in a format no writer has is a usage error found before the input is read:
// the input here is not even a mesh file (exit 1, not 2), and nothing is written.
TEST_F(OutputSafety, AnUnwritableMeshFormatStopsTheRunBeforeReading) {
  std::ofstream(path("junk.vtu")) << "not a mesh";
  const std::pair<std::string, std::string> runs[] = {{"generate", "disk --dims 8,8"},
                                                      {"assign", path("junk.vtu")},
                                                      {"reconstruct", path("junk.vtu")},
                                                      {"adapt", path("junk.vtu")}};
  for (const auto& [tool, args] : runs) {
    const ToolRun r = run(tool, args + " -o " + path("out.obj") + " --json " + path("r.json"));
    EXPECT_EQ(r.code, 1) << tool << ": " << r.err;
    EXPECT_NE(r.err.find("unknown mesh file extension '.obj'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.obj"))) << tool;
    EXPECT_FALSE(fs::exists(path("r.json"))) << tool;
  }
  EXPECT_EQ(
      run("assign", path("junk.vtu") + " -o " + path("a.vtu") + " --partial " + path("p.stl")).code,
      1);
}

// A .vts or .pvts holds a structured grid only: adapt's and reconstruct's meshes never are
// one, so they refuse it before reading (the input here is not even a mesh file); assign and
// measure refuse it once they have read an unstructured input, before the work. Each wrote
// nothing after the whole run before.
TEST_F(OutputSafety, AStructuredFormatForAnUnstructuredMeshStopsTheRunFirst) {
  std::ofstream(path("junk.vtu")) << "not a mesh";
  for (const char* tool : {"reconstruct", "adapt"})
    for (const char* out : {"out.vts", "out.pvts"}) {
      const ToolRun r =
          run(tool, path("junk.vtu") + " -o " + path(out) + " --json " + path("r.json"));
      EXPECT_EQ(r.code, 1) << tool << ": " << r.err;
      EXPECT_NE(r.err.find("holds a structured grid, and this mesh is not one"), std::string::npos)
          << r.err;
      EXPECT_FALSE(fs::exists(path("r.json"))) << tool;
    }
  ASSERT_EQ(run("generate", "disk --dims 8,8 -o " + path("u.vtu")).code, 0);
  ASSERT_EQ(run("generate", "disk --dims 8,8 -o " + path("s.vts")).code, 0);
  const std::pair<std::string, std::string> after_reading[] = {
      {"assign", path("u.vtu") + " -o " + path("a.vts")},
      {"assign", path("u.vtu") + " -o " + path("a.vtu") + " --partial " + path("p.pvts")},
      {"measure", path("u.vtu") + " --quality-field " + path("q.vts")},
      {"measure",
       path("u.vtu") + " --reference " + path("u.vtu") + " --discrepancy-field " + path("d.vts")}};
  for (const auto& [tool, args] : after_reading) {
    const ToolRun r = run(tool, args + " --json " + path("r.json"));
    EXPECT_EQ(r.code, 1) << tool << " " << args << ": " << r.err;
    EXPECT_NE(r.err.find("holds a structured grid"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("r.json"))) << tool << " " << args;
  }
  // A structured input keeps its structure through assign.
  EXPECT_EQ(run("assign", path("s.vts") + " -o " + path("a.pvts")).code, 0);
  EXPECT_TRUE(fs::exists(path("a_0.vts")));
}

TEST_F(OutputSafety, DirectoriesFifosAndDevicesAsInputsAreBadInput) {
  fs::create_directories(dir_ / "adir");
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  const std::pair<std::string, std::string> cases[] = {
      {path("adir"), "directory"}, {path("fifo"), "FIFO"}, {"/dev/null", "character device"}};
  for (const auto& [input, kind] : cases) {
    const ToolRun r = run("measure", input);
    EXPECT_EQ(r.code, 2) << input;
    EXPECT_NE(r.err.find(input), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(kind), std::string::npos) << r.err;
  }
  EXPECT_EQ(run("assign", path("adir") + " -o " + path("o.vtu")).code, 2);
}

// The mesh is written to its temporary file, then --json blocks on a FIFO nobody reads:
// SIGTERM at that moment must remove the temporary file and end the tool by SIGTERM.
TEST_F(OutputSafety, SigtermDuringTheWritesLeavesNoTemporaryFile) {
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  const std::string tool = std::string(HEXADAPT_TOOLS_DIR) +
                           "/hexadapt-generate disk --dims 8,8 -q -o " + path("out.vtu") +
                           " --json " + path("fifo");
  const std::string script = tool + " & p=$!; for i in $(seq 300); do ls " + path(".out.vtu.") +
                             "*.tmp >/dev/null 2>&1 && break; sleep 0.1; done; kill -TERM $p; "
                             "wait $p; echo $? > " +
                             path("status");
  ASSERT_EQ(std::system(("bash -c '" + script + "'").c_str()), 0);
  EXPECT_EQ(test::file_content(dir_ / "status"), "143\n");  // 128 + SIGTERM
  EXPECT_FALSE(fs::exists(dir_ / "out.vtu"));
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_NE(e.path().extension(), ".tmp") << e.path();
}

TEST_F(OutputSafety, ThreadsAboveTheLimitAreAUsageError) {
  const ToolRun r = run("measure", path("in.vtu") + " --threads 70000");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1024"), std::string::npos) << r.err;
  EXPECT_EQ(run("measure", path("in.vtu") + " -q --threads 1024").code, 0);
}

}  // namespace
}  // namespace hexadapt
