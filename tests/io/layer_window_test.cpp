// ReadOptions::layers and structured_shape: one rank's layers of a structured grid, from a
// single file cut after reading or from the pieces of a parallel file that hold them alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_file.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

namespace fs = std::filesystem;

std::string list(int first, int last, double scale = 1) {
  std::string s;
  for (int i = first; i <= last; ++i) s += std::to_string(i * scale) + " ";
  return s;
}

// A rectilinear grid of 3 x 2 x 5 unit cells (z from 0 to 5, or 2D with nz = 0) and the part
// of it within point extent z0..z1, as an ascii .vtr: cell array `id` holds each cell's id in
// the whole grid, point array `h` each point's.
std::string vtr(int z0, int z1, bool flat = false) {
  const std::string e = "0 3 0 2 " + std::to_string(z0) + " " + std::to_string(z1);
  const std::string whole = flat ? "0 3 0 2 0 0" : e;
  std::string ids, hs;
  for (int k = z0; k < (flat ? 1 : z1); ++k)
    for (int c = 0; c < 6; ++c) ids += std::to_string(6 * k + c) + " ";
  for (int k = z0; k <= (flat ? 0 : z1); ++k)
    for (int p = 0; p < 12; ++p) hs += std::to_string(12 * k + p) + " ";
  return R"(<VTKFile type="RectilinearGrid" version="1.0"><RectilinearGrid WholeExtent=")" +
         (flat ? whole : e) + R"("><Piece Extent=")" + (flat ? whole : e) + R"(">
<PointData><DataArray type="Float64" Name="h" format="ascii">)" +
         hs + R"(</DataArray></PointData>
<CellData><DataArray type="Float64" Name="id" format="ascii">)" +
         ids + R"(</DataArray></CellData>
<Coordinates><DataArray type="Float64" format="ascii">)" +
         list(0, 3) + R"(</DataArray><DataArray type="Float64" format="ascii">)" + list(0, 2, 0.5) +
         R"(</DataArray><DataArray type="Float64" format="ascii">)" + (flat ? "0" : list(z0, z1)) +
         R"(</DataArray></Coordinates></Piece></RectilinearGrid></VTKFile>)";
}

class LayerWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: ctest runs them side by side.
    dir_ = fs::path(::testing::TempDir()) /
           (std::string("hexadapt_layers_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write("whole.vtr", vtr(0, 5));
    write("flat.vtr", vtr(0, 0, true));
    write("a.vtr", vtr(0, 2));
    write("b.vtr", vtr(2, 3));
    write("c.vtr", vtr(3, 5));
    write("p.pvtr", R"(<VTKFile type="PRectilinearGrid" version="1.0">
<PRectilinearGrid WholeExtent="0 3 0 2 0 5" GhostLevel="0">
<PPointData><PDataArray type="Float64" Name="h"/></PPointData>
<PCellData><PDataArray type="Float64" Name="id"/></PCellData>
<PCoordinates><PDataArray type="Float64"/><PDataArray type="Float64"/><PDataArray type="Float64"/></PCoordinates>
<Piece Extent="0 3 0 2 0 2" Source="a.vtr"/><Piece Extent="0 3 0 2 2 3" Source="b.vtr"/>
<Piece Extent="0 3 0 2 3 5" Source="c.vtr"/></PRectilinearGrid></VTKFile>)");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  static ReadOptions layers(int first, int end) {
    ReadOptions o;
    o.layers = {first, end};
    return o;
  }

  fs::path dir_;
};

// The window's mesh and arrays, and its structured shape, which the io tests' comparison
// leaves out (an unstructured file does not keep it).
void expect_same_window(const MeshData& a, const MeshData& b) {
  test::expect_same(a, b);
  EXPECT_EQ(a.structured_cells, b.structured_cells);
}

TEST_F(LayerWindow, ASingleFileIsCutToTheLayersAndTheirNodes) {
  const MeshData d = read_mesh(path("whole.vtr"), layers(1, 3));
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{3, 2, 2}));
  EXPECT_EQ(d.n_cells(), 12);
  EXPECT_EQ(d.find_cell_array("id")->values.front(), 6);   // cell layer 1 first
  EXPECT_EQ(d.find_point_array("h")->values.front(), 12);  // node layers 1 to 3
  EXPECT_EQ(d.find_point_array("h")->values.back(), 47);
  EXPECT_EQ(d.points.front().z(), 1);
  MeshData whole = read_mesh(path("whole.vtr"));
  keep_layers(whole, {1, 3}, "whole");
  expect_same_window(d, whole);
}

TEST_F(LayerWindow, AParallelFileReadsOnlyThePiecesOfTheLayers) {
  MeshData expected = read_mesh(path("whole.vtr"));
  keep_layers(expected, {2, 4}, "whole");
  expect_same_window(read_mesh(path("p.pvtr"), layers(2, 4)), expected);  // from b and c
  fs::remove(dir_ / "a.vtr");
  expect_same_window(read_mesh(path("p.pvtr"), layers(2, 4)), expected);  // a is not read
  MeshData low = read_mesh(path("whole.vtr"));
  keep_layers(low, {0, 1}, "whole");
  fs::remove(dir_ / "b.vtr");
  fs::remove(dir_ / "c.vtr");
  EXPECT_THROW(read_mesh(path("p.pvtr"), layers(0, 1)), IoError);  // a is gone
  write("a.vtr", vtr(0, 2));
  expect_same_window(read_mesh(path("p.pvtr"), layers(0, 1)), low);
}

TEST_F(LayerWindow, TheShapeOfAParallelFileComesFromItsHeader) {
  for (const char* piece : {"a.vtr", "b.vtr", "c.vtr"}) fs::remove(dir_ / piece);
  const StructuredShape s = structured_shape(path("p.pvtr"));
  EXPECT_EQ(s.dim, 3);
  EXPECT_EQ(s.cells, (std::array<int, 3>{3, 2, 5}));
  const StructuredShape flat = structured_shape(path("flat.vtr"));
  EXPECT_EQ(flat.dim, 2);
  EXPECT_EQ(flat.cells, (std::array<int, 3>{3, 2, 0}));
}

TEST_F(LayerWindow, TwoDimensionalGridsAreCutAcrossY) {
  const MeshData d = read_mesh(path("flat.vtr"), layers(1, 2));
  EXPECT_EQ(d.dim, 2);
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{3, 1, 0}));
  EXPECT_EQ(d.find_cell_array("id")->values, (std::vector<double>{3, 4, 5}));
  EXPECT_EQ(d.points.size(), 8u);
  EXPECT_EQ(d.points.front().y(), 0.5);
}

TEST_F(LayerWindow, LayersOutsideTheGridOrAnUnstructuredFileAreRefused) {
  EXPECT_THROW(read_mesh(path("whole.vtr"), layers(3, 6)), InputError);
  EXPECT_THROW(read_mesh(path("p.pvtr"), layers(2, 2)), InputError);
  MeshData d = read_mesh(path("whole.vtr"));
  write_mesh(d, path("u.vtu"));
  EXPECT_THROW(read_mesh(path("u.vtu"), layers(0, 1)), OptionError);
  EXPECT_THROW(structured_shape(path("u.vtu")), InputError);
}

}  // namespace
}  // namespace hexadapt::io
