// How the input was read travels with the stages: measure reads its --reference as assign
// read the input (arrays named with commas, a sum tolerance), without the flags repeated;
// given flags win.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/structured.h"
#include "tools/tool_fixture.h"

namespace hexadapt::test {
namespace {

class InputRecordTool : public ToolTest {
 protected:
  // A disk-like blob of "Body, Nose" in "air" on 8 x 6 cells, sums 1.002 where both meet.
  void write_input() const {
    io::MeshData data = io::from_mesh(make_quad_grid(8, 6));
    std::vector<double> body, air;
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 8; ++i) {
        const double b = i >= 2 && i <= 5 && j >= 1 && j <= 4 ? 1.0
                         : i >= 1 && i <= 6 && j <= 5       ? 0.4
                                                             : 0.0;
        body.push_back(b);
        air.push_back(b == 0.4 ? 0.602 : 1.0 - b);
      }
    data.set_cell_array({"Body, Nose", 1, io::ScalarType::float64, body});
    data.set_cell_array({"air", 1, io::ScalarType::float64, air});
    io::write_mesh(data, path("in.vtu"));
  }
};

// The record travels in a .vtu's field data and comment, in a legacy .vtk's field data (its
// 255-character title cannot hold it) and in an Exodus file's info records.
TEST_F(InputRecordTool, MeasureReadsTheReferenceAsAssignReadTheInput) {
  write_input();
  const std::string arrays = " --fractions 'Body, Nose' air";
  const std::string reading = arrays + " --sum-tolerance 0.003";
  for (const std::string ext : {".vtu", ".vtk", ".exo"}) {
    ToolRun r = run("assign", path("in.vtu") + " -o " + path("a" + ext) + reading);
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("adapt", path("a" + ext) + " -o " + path("o" + ext) + " -q");
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("measure", path("o" + ext) + " --reference " + path("in.vtu") + " -q --json " +
                           path("m.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(file_content(dir_ / "m.json"));
    EXPECT_EQ(j["reference_read_with"], "the record in the input") << ext;
    EXPECT_EQ(j["discrepancy"]["materials"].size(), 2u);
    // Flags given to measure replace the record: without --sum-tolerance, the default
    // refuses the sums.
    r = run("measure", path("o" + ext) + " --reference " + path("in.vtu") + " -q" + arrays);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("fractions sum to 1.002"), std::string::npos) << r.err;
    r = run("measure", path("o" + ext) + " --reference " + path("in.vtu") + " -q" + reading +
                           " --json " + path("m2.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(file_content(dir_ / "m2.json"))["reference_read_with"],
              "the flags");
  }
}

// A record that is not one is the input's fault, named as such.
TEST_F(InputRecordTool, AMalformedRecordIsAnInputError) {
  io::MeshData data = io::from_mesh(make_quad_grid(2, 2));
  data.set_cell_array({"vf_a", 1, io::ScalarType::float64, {1, 1, 0, 0}});
  data.set_cell_array({"vf_b", 1, io::ScalarType::float64, {0, 0, 1, 1}});
  data.set_cell_array({"material", 1, io::ScalarType::int32, {0, 0, 1, 1}});
  data.metadata.emplace_back("hexadapt_input", "{\"fractions\": 3}");
  io::write_mesh(data, path("m.vtu"));
  const ToolRun r = run("measure", path("m.vtu") + " --reference " + path("m.vtu") + " -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("hexadapt_input"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give the reading flags instead"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hexadapt::test
