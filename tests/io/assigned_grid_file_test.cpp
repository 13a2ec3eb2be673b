#include "hexadapt/io/assigned_grid_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/structured.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

// A 3 x 2 quad grid with three materials whose names hold a comma, a space and a backslash;
// cell c is mostly material c % 3.
AssignedGrid sample_grid() {
  AssignedGrid g;
  g.mesh = make_quad_grid(3, 2);
  g.fractions = Fractions(6, {"air", "Volume Fraction for Body, Nose", "a\\b"});
  g.material = CellMaterials(6, 0);
  for (CellId c : id_range<CellId>(6)) {
    const int m = c.value() % 3;
    for (int k = 0; k < 3; ++k) g.fractions(c, k) = k == m ? 0.75 : 0.125;
    g.material[c] = (m + 1) % 3;  // not the majority: the array is what is read
  }
  return g;
}

TEST(AssignedGridFile, RoundTripThroughEveryWriterKeepsNamesFractionsAndMaterials) {
  const AssignedGrid g = sample_grid();
  for (const char* ext : {".vtu", ".vtk"}) {
    const std::string path = test::temp_path(std::string("grid") + ext);
    write_mesh(to_mesh_data(g), path);
    const MeshData data = read_mesh(path);
    std::filesystem::remove(path);
    const AssignedGrid back = to_assigned_grid(data, {}, path);
    EXPECT_EQ(back.names(), g.names()) << ext;
    EXPECT_EQ(back.material.raw(), g.material.raw()) << ext;
    for (CellId c : id_range<CellId>(6))
      for (int m = 0; m < 3; ++m) EXPECT_EQ(back.fractions(c, m), g.fractions(c, m)) << ext;
    ASSERT_TRUE(std::holds_alternative<QuadMesh>(back.mesh));
    EXPECT_EQ(std::get<QuadMesh>(back.mesh).n_cells(), 6);
    const std::string* names = nullptr;
    for (const auto& [key, value] : data.metadata)
      if (key == "hexadapt_materials") names = &value;
    ASSERT_NE(names, nullptr) << ext;
    EXPECT_EQ(split_material_names(*names), g.names()) << ext;
  }
}

TEST(AssignedGridFile, MaterialComesFromTheSourceAsked) {
  const MeshData data = to_mesh_data(sample_grid());
  AssignedGridOptions o;
  o.material = MaterialSource::majority;
  const AssignedGrid majority = to_assigned_grid(data, o, "g.vtu");
  for (CellId c : id_range<CellId>(6)) EXPECT_EQ(majority.material[c], c.value() % 3);
  o.material = MaterialSource::none;
  EXPECT_FALSE(to_assigned_grid(data, o, "g.vtu").assigned());
  // A grid not assigned, read as assigned: the error names the file and the array.
  AssignedGrid bare = sample_grid();
  bare.material = {};
  try {
    to_assigned_grid(to_mesh_data(bare), {}, "bare.vtu");
    FAIL() << "a grid without materials was read as assigned";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bare.vtu");
    EXPECT_NE(std::string(e.what()).find("'material'"), std::string::npos) << e.what();
  }
}

TEST(AssignedGridFile, WritingAgainReplacesTheArraysAndNames) {
  AssignedGrid g = sample_grid();
  MeshData data = to_mesh_data(g);
  g.material[CellId(0)] = 2;
  put_assignment(g, data);
  int name_entries = 0;
  for (const auto& kv : data.metadata) name_entries += kv.first == "hexadapt_materials";
  EXPECT_EQ(name_entries, 1);
  EXPECT_EQ(data.find_cell_array("material")->values[0], 2);
  EXPECT_EQ(data.cell_data.size(), 4u);  // three fractions and the material
}

TEST(AssignedGridFile, NamesJoinAndSplitBack) {
  for (const std::vector<std::string>& names :
       {std::vector<std::string>{"a", "b"}, {"Body, Nose", "x"}, {"a\\", ",", "\\,"}, {""}, {}}) {
    const std::string joined = join_material_names(names);
    EXPECT_EQ(split_material_names(joined), names.empty() || names == std::vector<std::string>{""}
                                                ? std::vector<std::string>{}
                                                : names)
        << joined;
  }
  EXPECT_EQ(join_material_names({"a", "b"}), "a,b");  // files of plain names read as before
  EXPECT_EQ(split_material_names("air,Body\\, Nose"),
            (std::vector<std::string>{"air", "Body, Nose"}));
}

// One key written, every place a file may keep the names read.
TEST(MaterialNames, ReadFromEachPlaceAFileKeepsThem) {
  const std::vector<std::string> names{"air", "Volume Fraction for Body, Nose"};
  MeshData d;
  EXPECT_TRUE(material_names(d).empty());
  set_material_names(d, {"old"});
  set_material_names(d, names);
  ASSERT_EQ(d.metadata.size(), 1u);
  EXPECT_EQ(d.metadata[0].first, "hexadapt_materials");
  EXPECT_EQ(material_names(d), names);
  // The key of earlier adapt outputs.
  d.metadata = {{"materials", join_material_names(names)}};
  EXPECT_EQ(material_names(d), names);
  // A String field-data array, one name per line: a name holding a comma stays whole.
  d.metadata = {{"material_names", "air\nBody, Nose"}};
  EXPECT_EQ(material_names(d), (std::vector<std::string>{"air", "Body, Nose"}));
  // The project's own key first.
  d.metadata.emplace_back("hexadapt_materials", "gas");
  EXPECT_EQ(material_names(d), std::vector<std::string>{"gas"});
}

}  // namespace
}  // namespace hexadapt::io
