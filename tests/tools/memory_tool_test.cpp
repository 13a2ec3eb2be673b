// Memory: every tool checks its estimate against --max-memory before the work (exit 5, the
// estimate and the limit named, nothing written), and an allocation that fails anyway is
// exit 5 with a message, never exit 4.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tools/tool_fixture.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

using test::ToolRun;

class Memory : public test::ToolTest {};

TEST_F(Memory, AnEstimateAboveTheLimitStopsEveryStageBeforeItsWork) {
  ASSERT_EQ(run("generate", "disk --dims 16,16 -q -o " + path("vf.vtu")).code, 0);
  ASSERT_EQ(run("assign", path("vf.vtu") + " -q -o " + path("assign.vtu")).code, 0);
  ASSERT_EQ(run("adapt", path("assign.vtu") + " -q -o " + path("mesh.vtu")).code, 0);
  const std::string limit = " --max-memory 10K";
  const std::pair<std::string, std::string> stages[] = {
      {"generate", "disk --dims 16,16 -o " + path("g.vtu")},
      {"assign", path("vf.vtu") + " -o " + path("a.vtu")},
      {"reconstruct", path("assign.vtu") + " -o " + path("r.vtu")},
      {"adapt", path("assign.vtu") + " -o " + path("m.vtu")},
      {"measure", path("mesh.vtu") + " --reference " + path("vf.vtu")},
  };
  for (const auto& [tool, args] : stages) {
    const ToolRun r = run(tool, args + limit);
    EXPECT_EQ(r.code, 5) << tool << ": " << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << tool << ": " << r.err;
    EXPECT_NE(r.err.find("needs about"), std::string::npos) << tool << ": " << r.err;
  }
  for (const char* out : {"g.vtu", "a.vtu", "r.vtu", "m.vtu"}) EXPECT_FALSE(fs::exists(path(out)));
  // Within the limit nothing changes.
  EXPECT_EQ(run("assign", path("vf.vtu") + " -q -o " + path("a.vtu") + " --max-memory 1G").code, 0);
}

TEST_F(Memory, ALimitThatIsNotASizeIsAUsageError) {
  for (const char* bad : {"abc", "-1G", "12Q", "nan"}) {
    const ToolRun r = run("generate", std::string("disk -o ") + path("g.vtu") + " --max-memory " + bad);
    EXPECT_EQ(r.code, 1) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
  }
}

// Sanitizer runtimes reserve more address space than the limit allows: there the test
// cannot run.
#if defined(__SANITIZE_ADDRESS__)
#define HEXADAPT_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HEXADAPT_UNDER_ASAN 1
#endif
#endif

TEST_F(Memory, AnAllocationThatFailsIsExitFiveNotABug) {
#ifdef HEXADAPT_UNDER_ASAN
  GTEST_SKIP() << "address space limits do not apply under AddressSanitizer";
#else
  const ToolRun r = run("generate", "sphere --dims 600,600,600 -q --threads 1 -o " +
                                        path("big.vtu") + " --max-memory 1T",
                        "ulimit -v 1000000; ");
  EXPECT_EQ(r.code, 5) << r.err;
  EXPECT_NE(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("estimate"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("big.vtu")));
#endif
}

}  // namespace
}  // namespace hexadapt
