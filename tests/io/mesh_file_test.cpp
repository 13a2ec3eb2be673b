#include "hexadapt/io/mesh_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"
#include "hexadapt/mesh/structured.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

MeshData small_hexes() {
  MeshData d = from_mesh(make_hex_grid(2, 1, 1));
  DataArray a;
  a.name = "vf_a";
  a.values = {0.25, 1};
  d.set_cell_array(a);
  return d;
}

TEST(MeshFile, WritesAndReadsEachWritableFormat) {
  const MeshData d = small_hexes();
  for (const char* ext : {".vtk", ".vtu", ".VTK"}) {
    const std::string path = test::temp_path(std::string("out") + ext);
    write_mesh(d, path);
    const MeshData r = read_mesh(path);
    EXPECT_EQ(test::cell_ids(r), test::cell_ids(d)) << ext;
    EXPECT_EQ(r.points, d.points) << ext;
    ASSERT_NE(r.find_cell_array("vf_a"), nullptr) << ext;
    EXPECT_EQ(r.find_cell_array("vf_a")->values, d.find_cell_array("vf_a")->values) << ext;
    std::remove(path.c_str());
  }
}

// A .pvtu on one process: the piece <name>_0.vtu and the file naming it, read back whole.
TEST(MeshFile, WritesAPvtuOfOnePiece) {
  const MeshData d = small_hexes();
  const std::string path = test::temp_path("one.pvtu");
  write_mesh(d, path);
  const std::string piece = test::temp_path("one_0.vtu");
  const std::string xml = test::read_text(path);
  const std::string source = "Source=\"" + std::filesystem::path(piece).filename().string() + "\"";
  EXPECT_NE(xml.find(source), std::string::npos) << xml;
  for (const std::string& p : {path, piece}) {
    const MeshData r = read_mesh(p);
    EXPECT_EQ(test::cell_ids(r), test::cell_ids(d)) << p;
    EXPECT_EQ(r.points, d.points) << p;
    ASSERT_NE(r.find_cell_array("vf_a"), nullptr) << p;
    EXPECT_EQ(r.find_cell_array("vf_a")->values, d.find_cell_array("vf_a")->values) << p;
  }
  std::remove(path.c_str());
  std::remove(piece.c_str());
}

// A structured grid of 3 x 2 x 5 cells with a cell and a point array.
MeshData structured_hexes() {
  MeshData d = from_mesh(make_hex_grid(3, 2, 5));
  d.structured_cells = {3, 2, 5};
  DataArray c{"vf_a", 1, ScalarType::float64, {}}, p{"height", 1, ScalarType::float32, {}};
  for (index_t i = 0; i < d.n_cells(); ++i) c.values.push_back(0.01 * static_cast<double>(i));
  for (const Vec3& x : d.points) p.values.push_back(x.z());
  d.set_cell_array(c);
  d.set_point_array(p);
  return d;
}

// A .pvts on one process, and a .pvts of pieces cut across z, each a .vts placed by its
// origin: both read back as the whole grid, points, cells and arrays.
TEST(MeshFile, WritesAPvtsOfPiecesPlacedInTheWholeGrid) {
  const MeshData d = structured_hexes();
  const auto expect_whole = [&](const MeshData& r, const std::string& what) {
    EXPECT_EQ(r.structured_cells, d.structured_cells) << what;
    EXPECT_EQ(test::cell_ids(r), test::cell_ids(d)) << what;
    EXPECT_EQ(r.points, d.points) << what;
    ASSERT_NE(r.find_cell_array("vf_a"), nullptr) << what;
    EXPECT_EQ(r.find_cell_array("vf_a")->values, d.find_cell_array("vf_a")->values) << what;
    ASSERT_NE(r.find_point_array("height"), nullptr) << what;
    EXPECT_EQ(r.find_point_array("height")->values, d.find_point_array("height")->values) << what;
  };
  const std::string one = test::temp_path("one.pvts");
  write_mesh(d, one);
  EXPECT_EQ(piece_path(one, 0), test::temp_path("one_0.vts"));
  expect_whole(read_mesh(one), "one piece");

  const std::string cut = test::temp_path("cut.pvts");
  std::vector<StructuredPiece> pieces;
  for (const std::array<int, 2>& layers : {std::array<int, 2>{0, 2}, {2, 3}, {3, 5}}) {
    MeshData part = d;
    keep_layers(part, layers, "test");
    const std::string file = piece_path(cut, static_cast<int>(pieces.size()));
    write_vts(part, file, {}, {0, 0, layers[0]});
    pieces.push_back(
        {file.substr(file.find_last_of('/') + 1), {0, 0, layers[0]}, part.structured_cells});
  }
  write_pvts(d, d.structured_cells, pieces, cut);
  expect_whole(read_mesh(cut), "three pieces");
  std::ifstream text(cut);
  std::ostringstream xml;
  xml << text.rdbuf();
  EXPECT_NE(xml.str().find("WholeExtent=\"0 3 0 2 0 5\""), std::string::npos) << xml.str();
  EXPECT_NE(xml.str().find("Extent=\"0 3 0 2 2 3\""), std::string::npos) << xml.str();
  // A rank reads its layers only.
  ReadOptions window;
  window.layers = {{2, 5}};
  MeshData part = d;
  keep_layers(part, {2, 5}, "test");
  EXPECT_EQ(read_mesh(cut, window).points, part.points);
  for (const std::string& p :
       {one, piece_path(one, 0), cut, piece_path(cut, 0), piece_path(cut, 1), piece_path(cut, 2)})
    std::remove(p.c_str());
}

// A file larger than one read chunk, from disk (size known) and from a pipe (size unknown).
TEST(MeshFile, ReadsLargeFilesAndPipes) {
  const MeshData d = from_mesh(make_hex_grid(16, 16, 16));
  const std::string path = test::temp_path("large.vtk");
  write_mesh(d, path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream copy;
  copy << in.rdbuf();
  const std::string bytes = copy.str();
  ASSERT_GT(bytes.size(), std::size_t(1) << 17);
  EXPECT_EQ(test::cell_ids(read_mesh(path)), test::cell_ids(d));

  const std::string fifo = test::temp_path("pipe.vtk");
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << bytes; });
  MeshData r;
  EXPECT_NO_THROW(r = read_mesh(fifo));
  writer.join();
  EXPECT_EQ(test::cell_ids(r), test::cell_ids(d));
  EXPECT_EQ(r.points, d.points);
  std::remove(path.c_str());
  std::remove(fifo.c_str());
}

TEST(MeshFile, TextCasesByExtension) {
  const std::string path = test::temp_path("case.txt");
  std::ofstream(path) << "2\n1 1\n1\n1\n0 a\n1\n0 1\n";
  EXPECT_EQ(read_mesh(path).find_cell_array("vf_a")->values, std::vector<double>{1});
  std::remove(path.c_str());
}

TEST(MeshFile, UnknownExtensionsListTheSupportedOnes) {
  try {
    write_mesh(small_hexes(), test::temp_path("out.obj"));
    FAIL() << "no error";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find(".vtu .vts .pvtu .pvts .vtk"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read_mesh(test::temp_path("in.stl")), OptionError);
  EXPECT_THROW(read_mesh(test::temp_path("no_extension")), OptionError);
}

TEST(MeshFile, MissingFileIsAnIoErrorWithTheReason) {
  try {
    read_mesh(test::temp_path("does_not_exist.vtk"));
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("does_not_exist.vtk: cannot open: No such file"),
              std::string::npos)
        << e.what();
  }
}

TEST(MeshFile, MalformedContentIsAnInputErrorNamingTheFile) {
  const std::string path = test::temp_path("bad.vtk");
  std::ofstream(path)
      << "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n0 0\n";
  try {
    read_mesh(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.where(), "line 5");
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace hexadapt::io
