// End to end on a small asteroid: hexadapt-generate, -assign, -reconstruct --model, then
// hexadapt-adapt with and without the model; the report's correction figures.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

int run(const std::string& tool, const std::string& args) {
  const std::string cmd =
      std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-" + tool + " " + args + " 2>/dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

nlohmann::json load(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(CorrectionTool, AsteroidWithAndWithoutTheModel) {
  const fs::path dir = fs::temp_directory_path() / "hexadapt_correction_tool";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  ASSERT_EQ(run("generate", "asteroid --dims 10,10,10 -q -o " + d + "a.vtu"), 0);
  ASSERT_EQ(run("assign", d + "a.vtu -q -o " + d + "a.assign.vtu"), 0);
  ASSERT_EQ(run("reconstruct", d + "a.assign.vtu -q -o " + d + "a.pixels.vtu --model " + d +
                                   "a.model.vtk"),
            0);
  ASSERT_EQ(run("adapt", d + "a.assign.vtu -q -o " + d + "with.vtu --json " + d +
                             "with.json --correction --model " + d + "a.model.vtk"),
            0);
  const auto with = load(dir / "with.json");
  EXPECT_EQ(with["model"], d + "a.model.vtk");
  const auto& c = with["result"]["correction"];
  ASSERT_TRUE(c["ran"].get<bool>());
  EXPECT_GT(c["surface_quads"].get<int>(), 0);
  EXPECT_GE(c["min_quad_quality_after"].get<double>(), c["min_quad_quality_projected"].get<double>());
  EXPECT_GT(c["max_target_displacement"].get<double>(), 0.0);
  EXPECT_GE(c["max_target_displacement"].get<double>(), c["mean_target_displacement"].get<double>());
  bool step = false;
  for (const auto& s : with["result"]["steps"]) step |= s["name"] == "correct";
  EXPECT_TRUE(step);
  EXPECT_GE(with["result"]["min_quality"].get<double>(), 0.3);

  ASSERT_EQ(run("adapt", d + "a.assign.vtu -q -o " + d + "without.vtu --correction --json " + d +
                             "without.json"),
            0);
  const auto without = load(dir / "without.json");
  EXPECT_FALSE(without["result"]["correction"]["ran"].get<bool>());
  EXPECT_EQ(without["result"]["correction"]["skipped"], "no model given");
  // Off by default, model or not.
  ASSERT_EQ(run("adapt", d + "a.assign.vtu -q -o " + d + "off.vtu --json " + d + "off.json --model " +
                             d + "a.model.vtk"),
            0);
  EXPECT_EQ(load(dir / "off.json")["result"]["correction"]["skipped"], "disabled");

  // A model of other materials is refused as bad input.
  std::ifstream in(d + "a.model.vtk");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const auto at = text.find("materials:");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 10, " extra");
  std::ofstream(d + "other.vtk") << text;
  EXPECT_EQ(run("adapt", d + "a.assign.vtu -q -o " + d + "other.vtu --model " + d + "other.vtk"), 2);
  fs::remove_all(dir);
}

}  // namespace
