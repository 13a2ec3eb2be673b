// Files that are well formed but hostile: lattices whose extent claims far more than the file
// holds, NaN or infinite coordinates, two arrays with one name, huge or binary tokens, and
// invalid meshes. Each is an InputError (or MeshError) naming the file, raised before any
// allocation proportional to a claimed size.
#include <gtest/gtest.h>

#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/text_case.h"
#include "hexadapt/io/vtk_legacy.h"
#include "hexadapt/io/vtk_xml.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

// The message of the InputError that reading `content` as `file` throws ("" if none).
template <class Read>
std::string input_error(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string xml_error(const std::string& content, const std::string& file) {
  return input_error([&] { read_vtk_xml(content, file); });
}

std::string legacy_error(const std::string& content, const std::string& file) {
  return input_error([&] { read_vtk_legacy(content, file); });
}

TEST(HostileFiles, ImageDataWithAHugeExtentAndNoArraysIsRefused) {
  const std::string vti = R"(<VTKFile type="ImageData" version="1.0">
  <ImageData WholeExtent="0 1000 0 1000 0 1000" Origin="0 0 0" Spacing="1 1 1">
    <Piece Extent="0 1000 0 1000 0 1000"></Piece>
  </ImageData>
</VTKFile>)";
  const std::string m = xml_error(vti, "huge.vti");
  EXPECT_NE(m.find("huge.vti"), std::string::npos) << m;
  EXPECT_NE(m.find("1003003001 points"), std::string::npos) << m;
  EXPECT_NE(m.find("no point or cell array"), std::string::npos) << m;
}

TEST(HostileFiles, RectilinearGridWithAHugeExtentAndNoArraysIsRefused) {
  const std::string vtr = R"(<VTKFile type="RectilinearGrid" version="1.0">
  <RectilinearGrid WholeExtent="0 1000 0 1000 0 1000">
    <Piece Extent="0 1000 0 1000 0 1000">
      <Coordinates>
        <DataArray type="Float64" format="ascii">0 1</DataArray>
        <DataArray type="Float64" format="ascii">0 1</DataArray>
        <DataArray type="Float64" format="ascii">0 1</DataArray>
      </Coordinates>
    </Piece>
  </RectilinearGrid>
</VTKFile>)";
  const std::string m = xml_error(vtr, "huge.vtr");
  EXPECT_NE(m.find("huge.vtr"), std::string::npos) << m;
  EXPECT_NE(m.find("1003003001 points"), std::string::npos) << m;
}

TEST(HostileFiles, ImageDataWithAHugeExtentAndAShortArrayIsRefused) {
  const std::string vti = R"(<VTKFile type="ImageData" version="1.0">
  <ImageData WholeExtent="0 1000 0 1000 0 1000" Origin="0 0 0" Spacing="1 1 1">
    <Piece Extent="0 1000 0 1000 0 1000">
      <CellData><DataArray type="Float64" Name="vf_a" format="ascii">1 1 1</DataArray></CellData>
    </Piece>
  </ImageData>
</VTKFile>)";
  const std::string m = xml_error(vti, "short.vti");
  EXPECT_NE(m.find("short.vti"), std::string::npos) << m;
}

TEST(HostileFiles, StructuredGridWithAHugeExtentAndShortPointsIsRefused) {
  const std::string vts = R"(<VTKFile type="StructuredGrid" version="1.0">
  <StructuredGrid WholeExtent="0 1000 0 1000 0 1000">
    <Piece Extent="0 1000 0 1000 0 1000">
      <Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0</DataArray></Points>
    </Piece>
  </StructuredGrid>
</VTKFile>)";
  const std::string m = xml_error(vts, "huge.vts");
  EXPECT_NE(m.find("huge.vts"), std::string::npos) << m;
}

TEST(HostileFiles, NanAndInfiniteCoordinatesAreRefusedWithThePointNumber) {
  const std::string quad =
      "DATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 1 X 0 0 1 0\n"
      "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n9\n";
  for (const char* bad : {"nan", "inf", "-inf"}) {
    std::string file = test::kLegacyHead + quad;
    file.replace(file.find('X'), 1, bad);
    const std::string m = legacy_error(file, "nan.vtk");
    EXPECT_NE(m.find("nan.vtk"), std::string::npos) << bad << ": " << m;
    EXPECT_NE(m.find("point 2"), std::string::npos) << bad << ": " << m;
    EXPECT_NE(m.find("finite"), std::string::npos) << bad << ": " << m;
  }
  const std::string sp = test::kLegacyHead +
                         "DATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 1\nSPACING 1 1 1\n"
                         "ORIGIN 0 nan 0\n";
  const std::string m = legacy_error(sp, "sp.vtk");
  EXPECT_NE(m.find("point 0"), std::string::npos) << m;
  const std::string vtu = R"(<VTKFile type="UnstructuredGrid" version="1.0">
  <UnstructuredGrid>
    <Piece NumberOfPoints="4" NumberOfCells="1">
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 1 1 0 0 inf 0</DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">9</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>)";
  const std::string x = xml_error(vtu, "inf.vtu");
  EXPECT_NE(x.find("inf.vtu"), std::string::npos) << x;
  EXPECT_NE(x.find("point 3"), std::string::npos) << x;
}

TEST(HostileFiles, LegacyReaderRefusesTwoArraysWithOneName) {
  const std::string file = test::kLegacyHead +
                           "DATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 1\nSPACING 1 1 1\n"
                           "ORIGIN 0 0 0\nCELL_DATA 2\nSCALARS vf_a double 1\nLOOKUP_TABLE "
                           "default\n0.25 1\nSCALARS vf_a double 1\nLOOKUP_TABLE default\n0 0\n";
  const std::string m = legacy_error(file, "twice.vtk");
  EXPECT_NE(m.find("twice.vtk"), std::string::npos) << m;
  EXPECT_NE(m.find("two CELL_DATA arrays named 'vf_a'"), std::string::npos) << m;
  // The same name in point data and in cell data is two different arrays.
  const std::string both = test::kLegacyHead +
                           "DATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 1\nSPACING 1 1 1\n"
                           "ORIGIN 0 0 0\nCELL_DATA 2\nSCALARS t double 1\nLOOKUP_TABLE "
                           "default\n0.25 1\nPOINT_DATA 6\nSCALARS t double 1\nLOOKUP_TABLE "
                           "default\n1 2 3 4 5 6\n";
  EXPECT_EQ(legacy_error(both, "both.vtk"), "");
}

TEST(HostileFiles, QuotedTokensAreCutAndEscaped) {
  EXPECT_EQ(quote_token("ASCII"), "'ASCII'");
  EXPECT_EQ(quote_token(std::string("a\x01\x7f", 3)), "'a\\x01\\x7f'");
  EXPECT_EQ(quote_token(std::string(1000, 'z')), "'" + std::string(40, 'z') + "...'");
  // As a reader echoes them: a 100 kB binary word on line 3.
  const std::string word = std::string(100000, 'B') + "\x01";
  const std::string m = legacy_error("# vtk DataFile Version 3.0\nt\n\x01" + word + "\n", "w.vtk");
  EXPECT_NE(m.find("w.vtk"), std::string::npos) << m;
  EXPECT_NE(m.find("'\\x01BBB"), std::string::npos) << m;
  EXPECT_LT(m.size(), 300u) << m;
}

TEST(HostileFiles, InvalidMeshErrorsNameTheFile) {
  MeshData d;
  d.dim = 2;
  d.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  d.cells = {NodeId(0), NodeId(1), NodeId(1), NodeId(3)};
  try {
    to_mesh(d, "repeat.vtk");
    FAIL() << "no MeshError";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("repeat.vtk: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("repeats a node"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hexadapt::io
