// A temporary folder per test and a way to run a hexadapt tool in it: what the tool tests of
// hostile command lines and files share.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace hexadapt::test {

struct ToolRun {
  int code = -1;
  std::string out, err;
};

inline std::string file_content(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class ToolTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("hexadapt_" + std::string(::testing::UnitTest::GetInstance()->current_test_suite()->name()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // Runs `prefix` hexadapt-<tool> args through the shell, with a time limit (a FIFO input
  // must not hang the test; no memory limit here: sanitizer builds reserve terabytes).
  ToolRun run(const std::string& tool, const std::string& args,
              const std::string& prefix = "") const {
    const std::string cmd = prefix + "timeout 120 " + std::string(HEXADAPT_TOOLS_DIR) +
                            "/hexadapt-" + tool + " " + args + " >" + path("stdout.txt") +
                            " 2>" + path("stderr.txt");
    const int status = std::system(cmd.c_str());
    ToolRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = file_content(dir_ / "stdout.txt");
    r.err = file_content(dir_ / "stderr.txt");
    std::filesystem::remove(dir_ / "stdout.txt");
    std::filesystem::remove(dir_ / "stderr.txt");
    return r;
  }

  std::filesystem::path dir_;
};

}  // namespace hexadapt::test
