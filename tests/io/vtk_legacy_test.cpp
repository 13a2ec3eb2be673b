#include "hexadapt/io/vtk_legacy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "hexadapt/core/error.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

TEST(VtkLegacy, StructuredPoints2DWithNamedLookupTable) {
  const MeshData d =
      read_vtk_legacy(test::kLegacyHead +
                          "DATASET STRUCTURED_POINTS\n"
                          "DIMENSIONS 3 2 1\nSPACING 0.5 2 1\nORIGIN 1 0 0\n"
                          "CELL_DATA 2\nSCALARS vf_a double 1\nLOOKUP_TABLE mine\n"
                          "0.25 1\nPOINT_DATA 6\nSCALARS t int\nLOOKUP_TABLE default\n"
                          "1 2 3 4 5 6\n",
                      "sp.vtk");
  ASSERT_EQ(d.dim, 2);
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{2, 1, 0}));
  EXPECT_EQ(d.points[5], Vec3(2, 2, 0));
  EXPECT_EQ(test::cell_ids(d), (std::vector<int>{0, 1, 4, 3, 1, 2, 5, 4}));
  const DataArray* a = d.find_cell_array("vf_a");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->type, ScalarType::float64);
  EXPECT_EQ(a->values, (std::vector<double>{0.25, 1}));
  const DataArray* t = d.find_point_array("t");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->type, ScalarType::int32);
  EXPECT_EQ(t->values[5], 6);
  EXPECT_EQ(d.metadata.at(0), (std::pair<std::string, std::string>{"title", "test case"}));
}

TEST(VtkLegacy, StructuredPoints3DAndFlatAxisMappedToXY) {
  const MeshData d3 = read_vtk_legacy(
      test::kLegacyHead + "DATASET STRUCTURED_POINTS\nDIMENSIONS 2 3 4\nORIGIN 0 0 0\nSPACING 1 1 1\n",
      "3d.vtk");
  EXPECT_EQ(d3.dim, 3);
  EXPECT_EQ(d3.n_cells(), 6);
  EXPECT_EQ(d3.structured_cells, (std::array<int, 3>{1, 2, 3}));
  // Flat along x: the (y, z) plane becomes (x, y).
  const MeshData d2 = read_vtk_legacy(
      test::kLegacyHead + "DATASET STRUCTURED_POINTS\nDIMENSIONS 1 3 2\nORIGIN 7 0 0\nSPACING 1 1 1\n",
      "yz.vtk");
  EXPECT_EQ(d2.dim, 2);
  EXPECT_EQ(d2.n_cells(), 2);
  EXPECT_EQ(d2.points[5], Vec3(2, 1, 7));
}

TEST(VtkLegacy, RectilinearGridKeepsCoordinatesAndCellOrder) {
  const MeshData d =
      read_vtk_legacy(test::kLegacyHead +
                          "DATASET RECTILINEAR_GRID\nDIMENSIONS 3 2 1\n"
                          "X_COORDINATES 3 float\n0 1 3\nY_COORDINATES 2 double\n"
                          "0 0.5\nZ_COORDINATES 1 int\n0\n"
                          "CELL_DATA 2\nSCALARS m unsigned_char\nLOOKUP_TABLE default\n"
                          "7 9\n",
                      "rg.vtk");
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.points[2], Vec3(3, 0, 0));
  EXPECT_EQ(d.points[4], Vec3(1, 0.5, 0));
  EXPECT_EQ(d.find_cell_array("m")->type, ScalarType::uint8);
  EXPECT_EQ(d.find_cell_array("m")->values, (std::vector<double>{7, 9}));
  EXPECT_EQ(d.points[5], Vec3(3, 0.5, 0));
}

TEST(VtkLegacy, AsciiNumbersInEveryNotation) {
  const MeshData d =
      read_vtk_legacy(test::kLegacyHead +
                          "DATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 1\n"
                          "X_COORDINATES 2 double\n+0 1e+00\nY_COORDINATES 2 double\n"
                          "-1.5E-1 .5\nZ_COORDINATES 1 double\n0\n"
                          "CELL_DATA 1\nSCALARS s double\nLOOKUP_TABLE default\nnan\n"
                          "POINT_DATA 4\nSCALARS p double\nLOOKUP_TABLE default\n"
                          "inf -inf +2 -0\n",
                      "num.vtk");
  EXPECT_EQ(d.points[3], Vec3(1, 0.5, 0));
  EXPECT_EQ(d.points[0].y(), -0.15);
  EXPECT_TRUE(std::isnan(d.cell_data[0].values[0]));
  EXPECT_EQ(d.point_data[0].values, (std::vector<double>{HUGE_VAL, -HUGE_VAL, 2, 0}));
}

TEST(VtkLegacy, StructuredGridWithVectorsAndMetadata) {
  const MeshData d = read_vtk_legacy(
      test::kLegacyHead +
          "DATASET STRUCTURED_GRID\nDIMENSIONS 2 2 1\nPOINTS 4 float\n0 0 0 1 0 0 0 1 0 1 1.5 0\n"
          "METADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 1.8\n\n"
          "POINT_DATA 4\nVECTORS v double\n1 2 3 4 5 6 7 8 9 10 11 12\n"
          "NORMALS n float\n0 0 1 0 0 1 0 0 1 0 0 1\n",
      "sg.vtk");
  EXPECT_EQ(d.n_cells(), 1);
  EXPECT_EQ(d.points[3], Vec3(1, 1.5, 0));
  EXPECT_EQ(d.find_point_array("v")->n_components, 3);
  EXPECT_EQ(d.find_point_array("v")->values[11], 12);
  EXPECT_EQ(d.find_point_array("n")->type, ScalarType::float32);
}

const std::string kTwoQuads =
    "DATASET UNSTRUCTURED_GRID\nPOINTS 6 double\n0 0 0 1 0 0 2 0 0 0 1 0 1 1 0 2 1 0\n";

TEST(VtkLegacy, UnstructuredClassicQuadsPixelsAndFields) {
  const MeshData d = read_vtk_legacy(
      test::kLegacyHead + kTwoQuads +
          "CELLS 2 10\n4 0 1 4 3\n4 1 2 4 5\nCELL_TYPES 2\n9 8\n"
          "CELL_DATA 2\nSCALARS two float 2\nLOOKUP_TABLE default\n1 2 3 4\n"
          "FIELD FieldData 2\nf%20x 3 2 short\n1 2 3 4 5 6\nMETADATA\nINFORMATION 0\n\n"
          "g 1 2 vtktypeint64\n-5 5\n",
      "ug.vtk");
  ASSERT_EQ(d.dim, 2);
  // The pixel (1 2 4 5) becomes the counter-clockwise quad 1 2 5 4.
  EXPECT_EQ(test::cell_ids(d), (std::vector<int>{0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(d.find_cell_array("two")->n_components, 2);
  const DataArray* f = d.find_cell_array("f x");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->type, ScalarType::int16);
  EXPECT_EQ(f->n_components, 3);
  EXPECT_EQ(d.find_cell_array("g")->type, ScalarType::int64);
  EXPECT_EQ(d.find_cell_array("g")->values[0], -5);
}

const std::string kCubePoints = "POINTS 8 float\n0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1\n";

TEST(VtkLegacy, UnstructuredVersion51HexahedronToBinaryOrder) {
  const MeshData d = read_vtk_legacy(
      "# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      "FIELD FieldData 2\nTimeValue 1 1 double\n0.5\nnote 1 1 string\nmade%20by%20hand\n" +
          kCubePoints +
          "CELLS 2 8\nOFFSETS vtktypeint64\n0 8\nCONNECTIVITY vtktypeint64\n0 1 3 2 4 5 7 6\n"
          "CELL_TYPES 1\n12\n",
      "hex.vtk");
  ASSERT_EQ(d.dim, 3);
  EXPECT_EQ(test::cell_ids(d), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  const auto note = std::find_if(d.metadata.begin(), d.metadata.end(),
                                 [](const auto& kv) { return kv.first == "note"; });
  ASSERT_NE(note, d.metadata.end());
  EXPECT_EQ(note->second, "made by hand");
}

// Big-endian bytes of a value, as legacy binary files store them.
template <class T>
std::string be(T v) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &v, sizeof(T));
  std::reverse(s.begin(), s.end());
  return s;
}

std::string binary_voxel_file(bool offsets_layout) {
  std::string f = "# vtk DataFile Version " + std::string(offsets_layout ? "5.1" : "4.2") +
                  "\nbin\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n";
  for (int p = 0; p < 8; ++p)
    for (int a = 0; a < 3; ++a) f += be(static_cast<double>((p >> a) & 1));
  if (offsets_layout) {
    f += "\nCELLS 2 8\nOFFSETS vtktypeint64\n" + be<std::int64_t>(0) + be<std::int64_t>(8);
    f += "\nCONNECTIVITY vtktypeint32\n";
    for (int k = 0; k < 8; ++k) f += be<std::int32_t>(k);
  } else {
    f += "\nCELLS 1 9\n" + be<std::int32_t>(8);
    for (int k = 0; k < 8; ++k) f += be<std::int32_t>(k);
  }
  f += "\nCELL_TYPES 1\n" + be<std::int32_t>(11);
  f += "\nCELL_DATA 1\nSCALARS s unsigned_short 1\nLOOKUP_TABLE default\n" + be<std::uint16_t>(513);
  f += "\nFIELD FieldData 1\nv 3 1 float\n" + be(1.5f) + be(-2.0f) + be(3.0f);
  f += "\nPOINT_DATA 8\nSCALARS c char\nLOOKUP_TABLE default\n";
  for (int p = 0; p < 8; ++p) f += be(static_cast<std::int8_t>(-p));
  return f + "\n";
}

TEST(VtkLegacy, BinaryBothCellLayouts) {
  for (bool layout : {false, true}) {
    const MeshData d = read_vtk_legacy(binary_voxel_file(layout), "bin.vtk");
    ASSERT_EQ(d.dim, 3) << layout;
    EXPECT_EQ(test::cell_ids(d), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(d.points[6], Vec3(0, 1, 1));
    EXPECT_EQ(d.find_cell_array("s")->values, std::vector<double>{513});
    EXPECT_EQ(d.find_cell_array("s")->type, ScalarType::uint16);
    EXPECT_EQ(d.find_cell_array("v")->values, (std::vector<double>{1.5, -2, 3}));
    EXPECT_EQ(d.find_point_array("c")->values[7], -7);
    EXPECT_EQ(d.find_point_array("c")->type, ScalarType::int8);
  }
}

TEST(VtkLegacy, WriterRoundTripKeepsTypesAndHexOrder) {
  MeshData d = read_vtk_legacy(binary_voxel_file(false), "bin.vtk");
  DataArray big;
  big.name = "big id";
  big.type = ScalarType::int64;
  big.values = {-(1LL << 40)};
  d.set_cell_array(big);
  d.metadata = {{"tool", "hexadapt-test"}, {"options", std::string(400, 'x')}};
  const std::string path = test::temp_path("roundtrip.vtk");
  write_vtk_legacy(d, path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string content = buffer.str();
  const MeshData r = read_vtk_legacy(content, path);
  EXPECT_EQ(test::cell_ids(r), test::cell_ids(d));
  EXPECT_EQ(r.points, d.points);
  ASSERT_EQ(r.cell_data.size(), 3u);
  for (const DataArray& a : d.cell_data) {
    const DataArray* b = r.find_cell_array(a.name);
    ASSERT_NE(b, nullptr) << a.name;
    EXPECT_EQ(b->type, a.type);
    EXPECT_EQ(b->n_components, a.n_components);
    EXPECT_EQ(b->values, a.values);
  }
  EXPECT_EQ(r.find_point_array("c")->values, d.find_point_array("c")->values);
  // The classic layout, and hexahedra in VTK's own order: 0 1 3 2 4 5 7 6 of the voxel.
  EXPECT_NE(content.find("# vtk DataFile Version 4.2\n"), std::string::npos);
  const std::size_t cells = content.find("CELLS 1 9\n");
  ASSERT_NE(cells, std::string::npos);
  EXPECT_EQ(content.substr(cells + 10 + 4 * 3, 4), be<std::int32_t>(3));
  // The title holds whole key=value pairs only: the 400-character options do not fit the
  // 255 characters, so they are left out rather than cut in the middle, and the title says so.
  EXPECT_NE(content.find("\nhexadapt: tool=hexadapt-test; ... 1 more\nBINARY\n"),
            std::string::npos);
  EXPECT_EQ(r.metadata, d.metadata);  // whole, from the field data
  std::remove(path.c_str());
}

std::string written_legacy(const MeshData& d, const std::string& name) {
  const std::string path = test::temp_path(name);
  write_vtk_legacy(d, path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::remove(path.c_str());
  return buffer.str();
}

// A file made by a second tool from the first one's: both tools' provenance, a long command
// with characters a title or an XML comment cannot hold as they are.
std::vector<std::pair<std::string, std::string>> pipeline_metadata(const std::string& command) {
  return {{"hexadapt_case", "triple-point"},
          {"hexadapt_tool", "hexadapt-generate"},
          {"hexadapt_version", "0.1.0"},
          {"hexadapt_command", "hexadapt-generate triple-point -o in.vtu"},
          {"hexadapt_tool", "hexadapt-adapt"},
          {"hexadapt_version", "0.1.0"},
          {"hexadapt_command", command},
          {"materials", "left,bottom,top"}};
}

TEST(VtkLegacy, TitleHasWholePairsThisFilesFirstAndTheCommandIsKeptExactly) {
  MeshData d = read_vtk_legacy(binary_voxel_file(false), "bin.vtk");
  const std::string command = "hexadapt-adapt '/data/run 7/case.assign.vtu' --model " +
                              std::string(200, 'm') + ".vtk --threshold 0.3 -o 'it'\\''s.vtu'";
  d.metadata = pipeline_metadata(command);
  const std::string content = written_legacy(d, "provenance.vtk");
  const std::size_t title_at = content.find('\n') + 1;
  const std::string title = content.substr(title_at, content.find('\n', title_at) - title_at);
  EXPECT_LE(title.size(), 255u);
  // The tool that wrote the file first; the command does not fit, the rest does.
  EXPECT_EQ(title,
            "hexadapt: hexadapt_tool=hexadapt-adapt; hexadapt_version=0.1.0; "
            "materials=left,bottom,top; hexadapt_case=triple-point; "
            "hexadapt_tool=hexadapt-generate; hexadapt_version=0.1.0; "
            "hexadapt_command=hexadapt-generate triple-point -o in.vtu; ... 1 more");
  // The command whole, in the data set's field data, then every entry; read back as they were.
  EXPECT_NE(
      content.find("\nFIELD FieldData 2\nhexadapt_command 1 " + std::to_string(command.size()) +
                   " char\n" + command + "\nhexadapt_metadata 1 "),
      std::string::npos);
  const MeshData r = read_vtk_legacy(content, "provenance.vtk");
  EXPECT_EQ(r.metadata, d.metadata);
  EXPECT_EQ(r.points, d.points);
  // A file with the command array alone (written before the metadata array) gives it back.
  const std::size_t whole = content.find("hexadapt_metadata 1 ");
  std::string older = content.substr(0, whole) + content.substr(content.find("\nCELL_DATA") + 1);
  older.replace(older.find("FieldData 2"), 11, "FieldData 1");
  std::vector<std::string> commands;
  for (const auto& [key, value] : read_vtk_legacy(older, "older.vtk").metadata)
    if (key == "hexadapt_command") commands.push_back(value);
  EXPECT_EQ(commands, std::vector<std::string>{command});
}

TEST(VtkLegacy, TitleThatFitsHasNoMarkAndNoCommandMeansNoCommandArray) {
  MeshData d = read_vtk_legacy(binary_voxel_file(false), "bin.vtk");
  d.metadata = {{"hexadapt_tool", "hexadapt-test"}, {"note", "two\nlines"}};
  const std::string content = written_legacy(d, "short.vtk");
  EXPECT_NE(content.find("\nhexadapt: hexadapt_tool=hexadapt-test; note=two lines\nBINARY\n"),
            std::string::npos);
  EXPECT_EQ(content.find("hexadapt_command"), std::string::npos);
  EXPECT_EQ(read_vtk_legacy(content, "short.vtk").metadata, d.metadata);  // the line break too
}

struct Malformed {
  const char* name;
  std::string content;
  std::vector<std::string> fragments;  ///< every one must appear in the message
};

const std::string kHexCells = "CELLS 1 9\n8 0 1 3 2 4 5 7 6\nCELL_TYPES 1\n12\n";

std::vector<Malformed> malformed_cases() {
  const std::string ug = test::kLegacyHead + "DATASET UNSTRUCTURED_GRID\n";
  const std::string bin = "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  return {
      {"not vtk", "hello\n", {"line 1", "not a legacy VTK file"}},
      {"no mode", "# vtk DataFile Version 3.0\nt\nTEXT\n", {"line 3", "ASCII or BINARY"}},
      {"no dataset", test::kLegacyHead + "POINTS 1 float\n", {"expected DATASET"}},
      {"polydata", test::kLegacyHead + "DATASET POLYDATA\n", {"unsupported data set type 'POLYDATA'"}},
      {"truncated points",
       ug + "POINTS 4 float\n0 0 0 1 0 0\n",
       {"line 5", "ends before the 12 point coordinates"}},
      {"lying point count", ug + "POINTS 99999999999 float\n0 0 0\n", {"out of range"}},
      {"ascii too few bytes", ug + "POINTS 1000 float\n0 0 0\n", {"3000 point coordinates"}},
      {"bad number", ug + "POINTS 1 float\n0 0 x\n", {"line 6", "found 'x'"}},
      {"triangle",
       ug + kCubePoints + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n",
       {"cell 0", "unsupported VTK cell type 5"}},
      {"wrong cells size",
       ug + kCubePoints + "CELLS 1 10\n8 0 1 3 2 4 5 7 6 0\nCELL_TYPES 1\n12\n",
       {"line 7", "CELLS size is 10 but its 1 cells use 9 entries"}},
      {"cell past size",
       ug + kCubePoints + "CELLS 1 5\n8 0 1 3 2\nCELL_TYPES 1\n12\n",
       {"cell 0 does not fit"}},
      {"cell types count",
       ug + kCubePoints + "CELLS 1 9\n8 0 1 3 2 4 5 7 6\nCELL_TYPES 2\n12 12\n",
       {"line 9", "CELL_TYPES 2 does not match the 1 cells"}},
      {"node out of range",
       ug + kCubePoints + "CELLS 1 9\n8 0 1 3 2 4 5 7 8\nCELL_TYPES 1\n12\n",
       {"cell 0", "node id 8 out of range"}},
      {"no cell types",
       ug + kCubePoints + "CELLS 1 9\n8 0 1 3 2 4 5 7 6\n",
       {"CELLS without CELL_TYPES"}},
      {"types before cells", ug + kCubePoints + "CELL_TYPES 1\n12\n", {"CELL_TYPES before CELLS"}},
      {"mixed dimensions",
       ug + kCubePoints + "CELLS 2 14\n8 0 1 3 2 4 5 7 6\n4 0 1 3 2\nCELL_TYPES 2\n12 9\n",
       {"cell 1", "mixes 2D and 3D"}},
      {"bad offsets",
       ug + kCubePoints +
           "CELLS 2 8\nOFFSETS vtktypeint64\n1 8\nCONNECTIVITY vtktypeint64\n0 1 3 2 4 5 7 6\n",
       {"OFFSETS must start at 0"}},
      {"missing connectivity",
       ug + kCubePoints + "CELLS 2 8\nOFFSETS vtktypeint64\n0 8\nCELL_TYPES 1\n12\n",
       {"expected CONNECTIVITY"}},
      {"cell data count",
       ug + kCubePoints + kHexCells + "CELL_DATA 3\n",
       {"line 11", "CELL_DATA 3 does not match the 1 cells"}},
      {"point data count", ug + kCubePoints + kHexCells + "POINT_DATA 7\n", {"POINT_DATA 7"}},
      {"unknown data keyword",
       ug + kCubePoints + kHexCells + "CELL_DATA 1\nFOO x\n",
       {"line 12", "unknown keyword 'FOO'"}},
      {"unknown geometry keyword", ug + "BLAH 3\n", {"line 5", "'BLAH'"}},
      {"bit array", ug + kCubePoints + kHexCells + "CELL_DATA 1\nSCALARS b bit\n", {"bit arrays"}},
      {"unknown type", ug + "POINTS 1 quad\n", {"unknown data type 'quad'"}},
      {"float ids", ug + kCubePoints + "CELLS 2 8\nOFFSETS float\n0 8\n", {"integer type"}},
      {"too many components",
       ug + kCubePoints + kHexCells + "CELL_DATA 1\nSCALARS s float 7\n",
       {"out of range [1, 4]"}},
      {"field tuples",
       ug + kCubePoints + kHexCells + "CELL_DATA 1\nFIELD F 1\na 1 2 float\n1 2\n",
       {"line 13", "field array 'a' has 2 tuples, expected 1"}},
      {"truncated array",
       ug + kCubePoints + kHexCells + "CELL_DATA 1\nSCALARS s float\nLOOKUP_TABLE default\n",
       {"end of file", "array values"}},
      {"rectilinear count",
       test::kLegacyHead + "DATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 1\nX_COORDINATES 3 float\n0 1 2\n",
       {"line 6", "expected 2 coordinates"}},
      {"rectilinear missing axis",
       test::kLegacyHead + "DATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 1\nX_COORDINATES 2 float\n0 1\n",
       {"needs X_COORDINATES, Y_COORDINATES and Z_COORDINATES"}},
      {"structured points count",
       test::kLegacyHead + "DATASET STRUCTURED_GRID\nDIMENSIONS 2 2 1\nPOINTS 5 float\n",
       {"POINTS 5 does not match DIMENSIONS (4 points)"}},
      {"zero dimension", test::kLegacyHead + "DATASET STRUCTURED_POINTS\nDIMENSIONS 2 0 1\n", {"out of range"}},
      {"huge dimensions",
       test::kLegacyHead + "DATASET STRUCTURED_POINTS\nDIMENSIONS 100000 100000 100000\n",
       {"32-bit ids"}},
      {"lattice without data",
       test::kLegacyHead + "DATASET STRUCTURED_POINTS\nDIMENSIONS 2000 2000 2\n",
       {"announce 8000000 points but only"}},
      {"line of points", test::kLegacyHead + "DATASET STRUCTURED_POINTS\nDIMENSIONS 5 1 1\n", {"single row"}},
      {"binary lying size",
       bin + "POINTS 100000000 float\n" + std::string(24, '\0'),
       {"byte 85", "300000000 point coordinates", "24 bytes left"}},
      {"binary truncated types",
       bin + "POINTS 1 double\n" + std::string(24, '\0') + "\nCELLS 0 0\nCELL_TYPES 0\n" +
           "CELL_DATA 0\nPOINT_DATA 1\nSCALARS s double 1\nLOOKUP_TABLE default\n" +
           std::string(5, '\0'),
       {"byte 191", "1 array values", "5 bytes left"}},
  };
}

TEST(VtkLegacy, MalformedFilesGiveThePlaceAndWhatWasExpected) {
  for (const Malformed& m : malformed_cases()) {
    try {
      read_vtk_legacy(m.content, "case.vtk");
      ADD_FAILURE() << m.name << ": no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("case.vtk: ", 0), 0u) << m.name << ": " << what;
      for (const std::string& f : m.fragments)
        EXPECT_NE(what.find(f), std::string::npos) << m.name << ": '" << f << "' not in: " << what;
    }
  }
}

TEST(VtkLegacy, EveryTruncationOfAValidFileFailsCleanly) {
  // No prefix of a file may crash or be read as a different complete mesh.
  for (bool layout : {false, true}) {
    const std::string full = binary_voxel_file(layout);
    for (std::size_t n = 0; n + 1 < full.size(); ++n) {
      try {
        const MeshData d = read_vtk_legacy(full.substr(0, n), "cut.vtk");
        // Only cuts between complete sections may succeed, with fewer arrays.
        EXPECT_LE(d.cell_data.size() + d.point_data.size(), 3u);
      } catch (const InputError&) {
      }
    }
  }
}

TEST(VtkLegacy, LargeAsciiFileParsesQuickly) {
  // 100 x 100 x 50 = 500 k hexes as an ASCII rectilinear grid with one cell array. Guards
  // against quadratic steps (the limit is loose for sanitizer builds); the time is recorded.
  const int nx = 100, ny = 100, nz = 50;
  std::string f = test::kLegacyHead + "DATASET RECTILINEAR_GRID\nDIMENSIONS 101 101 51\n";
  auto axis = [&](const char* name, int n) {
    f += std::string(name) + " " + std::to_string(n + 1) + " double\n";
    for (int i = 0; i <= n; ++i) f += std::to_string(0.01 * i) + " ";
    f += "\n";
  };
  axis("X_COORDINATES", nx), axis("Y_COORDINATES", ny), axis("Z_COORDINATES", nz);
  f += "CELL_DATA " + std::to_string(nx * ny * nz) +
       "\nSCALARS vf_a double 1\nLOOKUP_TABLE default\n";
  for (int c = 0; c < nx * ny * nz; ++c) f += c % 3 ? "0.333333333333 " : "1\n";
  const auto t0 = std::chrono::steady_clock::now();
  const MeshData d = read_vtk_legacy(f, "big.vtk");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(d.n_cells(), nx * ny * nz);
  EXPECT_LT(s, 10.0) << "reading " << f.size() << " bytes took " << s << " s";
  RecordProperty("seconds", std::to_string(s));
}

}  // namespace
}  // namespace hexadapt::io
