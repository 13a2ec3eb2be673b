// The material names the render tool shows (tools/render/coloring.h), from each place a file
// keeps them.
#ifdef HEXADAPT_HAVE_RENDER
#include "coloring.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hexadapt/io/assigned_grid_file.h"

namespace hexadapt::render {
namespace {

TEST(RenderColoring, MaterialNamesKeepTheirCommas) {
  const std::vector<std::string> names{"air", "Volume Fraction for Body, Nose"};
  io::MeshData d;
  d.metadata = {{"hexadapt_materials", io::join_material_names(names)}};
  EXPECT_EQ(material_names(d), names);
  d.metadata = {{"materials", io::join_material_names(names)}};
  EXPECT_EQ(material_names(d), names);
  // A String field-data array, one name per line: one name holding a comma stays whole.
  d.metadata = {{"material_names", "Body, Nose"}};
  EXPECT_EQ(material_names(d), std::vector<std::string>{"Body, Nose"});
  d.metadata = {{"material_names", "air\nBody, Nose"}};
  EXPECT_EQ(material_names(d), (std::vector<std::string>{"air", "Body, Nose"}));
}

}  // namespace
}  // namespace hexadapt::render
#endif
