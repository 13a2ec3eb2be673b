// The render tool's colouring (tools/render/coloring.h): the legend's names and the fields it
// colours by.
#ifdef HEXADAPT_HAVE_RENDER
#include "coloring.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/material_names.h"

namespace hexadapt::render {
namespace {

// The legend names the file's materials (io::material_names), or else its vf_ arrays.
TEST(RenderColoring, LegendNamesTheMaterials) {
  const std::vector<std::string> names{"air", "Volume Fraction for Body, Nose"};
  io::MeshData d;
  d.set_cell_array({"vf_gas", 1, io::ScalarType::float64, {}});
  d.set_cell_array({"vf_water", 1, io::ScalarType::float64, {}});
  EXPECT_EQ(legend_names(d), (std::vector<std::string>{"gas", "water"}));
  io::set_material_names(d, names);
  EXPECT_EQ(legend_names(d), names);
}

// Two unit quads side by side: nodes 0-2 along y = 0, 3-5 along y = 1.
io::MeshData two_quads() {
  io::MeshData d;
  d.dim = 2;
  for (double y : {0.0, 1.0})
    for (double x : {0.0, 1.0, 2.0}) d.points.emplace_back(x, y, 0);
  for (int i : {0, 1, 4, 3, 1, 2, 5, 4}) d.cells.emplace_back(i);
  return d;
}

TEST(RenderColoring, PointArrayColoursEachCellByTheMeanOfItsNodes) {
  io::MeshData d = two_quads();
  d.set_point_array({"distance", 1, io::ScalarType::float64, {0, 1, 6, 0, 1, 6}});
  d.set_cell_array({"material", 1, io::ScalarType::int32, {0, 1}});
  const CellColors c = color_cells(d, "distance");
  ASSERT_TRUE(c.bar.has_value());
  EXPECT_EQ(c.bar->data_min, 0.5);  // (0 + 1 + 1 + 0) / 4
  EXPECT_EQ(c.bar->data_max, 3.5);  // (1 + 6 + 6 + 1) / 4
  EXPECT_NE(c.bar->title.find("distance"), std::string::npos);
  EXPECT_EQ(c.cell[0], colormap(0));
  EXPECT_EQ(c.cell[1], colormap(1));

  // A node without a finite value leaves its cells without one (grey, "no value").
  d.point_data[0].values[2] = std::numeric_limits<double>::quiet_NaN();
  const CellColors n = color_cells(d, "distance");
  EXPECT_EQ(n.bar->data_min, 0.5);
  EXPECT_EQ(n.bar->data_max, 0.5);
  ASSERT_EQ(n.bar->special.size(), 1u);
  EXPECT_NE(n.cell[1], colormap(0));
}

TEST(RenderColoring, AnUnknownFieldNamesEachArrayOnce) {
  io::MeshData d = two_quads();
  d.set_point_array({"distance", 1, io::ScalarType::float64, std::vector<double>(6, 0.0)});
  d.set_cell_array({"material", 1, io::ScalarType::int32, {0, 1}});
  try {
    color_cells(d, "pressure");
    FAIL() << "no error";
  } catch (const OptionError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'pressure'"), std::string::npos) << m;
    EXPECT_NE(m.find("'distance'"), std::string::npos) << m;
    const auto first = m.find("material");
    ASSERT_NE(first, std::string::npos) << m;
    EXPECT_EQ(m.find("material", first + 1), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace hexadapt::render
#endif
