#include <gtest/gtest.h>

#include <cmath>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"

namespace hexadapt::io {
namespace {

// One unit hex as VTK_HEXAHEDRON (VTK's node order), ascii, with point, cell and field data.
const char* one_hex = R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1">
  <UnstructuredGrid>
    <FieldData>
      <DataArray type="String" Name="tool" NumberOfTuples="1" format="ascii">104 105 0</DataArray>
    </FieldData>
    <Piece NumberOfPoints="8" NumberOfCells="1">
      <PointData>
        <DataArray type="Float32" Name="d" format="ascii">0 1 2 3 4 5 6 nan</DataArray>
      </PointData>
      <CellData>
        <DataArray type="Int16" Name="material" format="ascii">-7</DataArray>
      </CellData>
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">
          0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3 4 5 6 7</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">8</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">12</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";

TEST(VtkXmlReader, HexahedronComesInBinaryOrderWithItsArrays) {
  const MeshData d = read_vtk_xml(one_hex, "one.vtu");
  ASSERT_EQ(d.dim, 3);
  ASSERT_EQ(d.n_cells(), 1);
  // Binary node b sits at (b & 1, b >> 1 & 1, b >> 2 & 1).
  for (int b = 0; b < 8; ++b)
    EXPECT_EQ(d.points[static_cast<std::size_t>(d.cells[static_cast<std::size_t>(b)].value())],
              Vec3(b & 1, b >> 1 & 1, b >> 2 & 1))
        << b;
  ASSERT_EQ(d.cell_data.size(), 1u);
  EXPECT_EQ(d.cell_data[0].type, ScalarType::int16);
  EXPECT_EQ(d.cell_data[0].values, std::vector<double>{-7});
  ASSERT_EQ(d.point_data.size(), 1u);
  EXPECT_EQ(d.point_data[0].type, ScalarType::float32);
  EXPECT_TRUE(std::isnan(d.point_data[0].values[7]));  // NaN is data; validation comes later
  ASSERT_EQ(d.metadata.size(), 1u);
  EXPECT_EQ(d.metadata[0], std::make_pair(std::string("tool"), std::string("hi")));
}

std::string with(std::string text, const std::string& find, const std::string& insert_after) {
  const std::size_t at = text.find(find);
  EXPECT_NE(at, std::string::npos) << find;
  return text.insert(at + find.size(), insert_after);
}

using Entries = std::vector<std::pair<std::string, std::string>>;

TEST(VtkXmlReader, MetadataCommentComesBeforeStringFieldData) {
  const std::string text = with(one_hex, "<?xml version=\"1.0\"?>\n",
                                "<!-- a comment of someone else -->\n"
                                "<!-- hexadapt metadata\n"
                                "command: run -\\x2Dx a\\x3Cb & c\n"
                                "lines: one\\ntwo\\\\n\\x2D\n"
                                "a\\x3Ab: : \n"
                                "-->\n");
  const MeshData d = read_vtk_xml(text, "c.vtu");
  EXPECT_EQ(d.metadata, (Entries{{"command", "run --x a<b & c"},
                                 {"lines", "one\ntwo\\n-"},
                                 {"a:b", ": "},
                                 {"tool", "hi"}}));
}

TEST(VtkXmlReader, MetadataCommentInsideVtkFileIsRead) {
  const std::string text =
      with(one_hex, "version=\"0.1\">", "\n  <!--hexadapt metadata  \r\nk: v\n\n-->");
  const MeshData d = read_vtk_xml(text, "c.vtu");
  EXPECT_EQ(d.metadata, (Entries{{"k", "v"}, {"tool", "hi"}}));
}

TEST(VtkXmlReader, CommentsThatAreNotOursAreIgnored) {
  for (const char* comment :
       {"<!-- hexadapt metadata -->",  // no entry lines: no newline
        "<!-- other title\nk: v\n-->", "<!-- hexadapt metadata\nno separator\n-->",
        "<!-- hexadapt metadata\nk: bad \\q escape\n-->",
        "<!-- hexadapt metadata\nk: short \\x4\n-->"}) {
    const MeshData d = read_vtk_xml(with(one_hex, "<?xml version=\"1.0\"?>\n", comment), "c.vtu");
    EXPECT_EQ(d.metadata, (Entries{{"tool", "hi"}})) << comment;
  }
}

TEST(VtkXmlReader, CommentInsideAsciiArrayIsSkipped) {
  const std::string text = with(one_hex, "Name=\"material\" format=\"ascii\">", "<!-- c -->");
  const MeshData d = read_vtk_xml(text, "c.vtu");
  ASSERT_EQ(d.cell_data.size(), 1u);
  EXPECT_EQ(d.cell_data[0].values, std::vector<double>{-7});
}

TEST(VtkXmlReader, ImageDataAppliesOriginSpacingAndDirection) {
  const char* vti = R"(<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian">
  <ImageData WholeExtent="1 3 0 1 0 0" Origin="10 20 30" Spacing="2 3 1" Direction="0 -1 0 1 0 0 0 0 1">
    <Piece Extent="1 3 0 1 0 0">
      <CellData><DataArray type="Float64" Name="vf_a" format="ascii">0.25 0.75</DataArray></CellData>
    </Piece>
  </ImageData>
</VTKFile>)";
  const MeshData d = read_vtk_xml(vti, "a.vti");
  ASSERT_EQ(d.dim, 2);
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{2, 1, 0}));
  ASSERT_EQ(d.points.size(), 6u);
  // Point (i=1, j=0): local (2, 0, 0), rotated by the direction matrix to (0, 2, 0).
  EXPECT_EQ(d.points[0], Vec3(10, 22, 30));
  // Point (i=3, j=1): local (6, 3, 0) -> (-3, 6, 0).
  EXPECT_EQ(d.points[5], Vec3(7, 26, 30));
  EXPECT_EQ(d.find_cell_array("vf_a")->values, (std::vector<double>{0.25, 0.75}));
}

TEST(VtkXmlReader, RectilinearGridTakesItsAxes) {
  const char* vtr = R"(<VTKFile type="RectilinearGrid">
  <RectilinearGrid WholeExtent="0 2 0 1 0 1">
    <Piece Extent="0 2 0 1 0 1">
      <Coordinates>
        <DataArray type="Float32" format="ascii">0 0.5 2</DataArray>
        <DataArray type="Float64" format="ascii">-1 1</DataArray>
        <DataArray type="Int32" format="ascii">3 7</DataArray>
      </Coordinates>
    </Piece>
  </RectilinearGrid>
</VTKFile>)";
  const MeshData d = read_vtk_xml(vtr, "a.vtr");
  ASSERT_EQ(d.dim, 3);
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.points.back(), Vec3(2, 1, 7));
  EXPECT_EQ(d.points[1], Vec3(0.5, -1, 3));
}

std::string two_quads(const char* connectivity, const char* types) {
  return std::string(R"(<VTKFile type="UnstructuredGrid">
  <UnstructuredGrid><Piece NumberOfPoints="6" NumberOfCells="2">
    <Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">
      0 0 5  1 0 5  2 0 5  0 1 5  1 1 5  2 1 5</DataArray></Points>
    <Cells>
      <DataArray type="Int64" Name="connectivity" format="ascii">)") +
         connectivity + R"(</DataArray>
      <DataArray type="Int64" Name="offsets" format="ascii">4 8</DataArray>
      <DataArray type="UInt8" Name="types" format="ascii">)" +
         types + R"(</DataArray>
    </Cells>
  </Piece></UnstructuredGrid>
</VTKFile>)";
}

std::vector<NodeId> ids(std::initializer_list<int> v) {
  std::vector<NodeId> out;
  for (int i : v) out.emplace_back(i);
  return out;
}

TEST(VtkXmlReader, ClockwiseQuadsBecomeCounterClockwise) {
  const MeshData d = read_vtk_xml(two_quads("0 3 4 1  1 4 5 2", "9 9"), "q.vtu");
  ASSERT_EQ(d.dim, 2);
  EXPECT_EQ(d.cells, ids({0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(d.points[0].z(), 5.0);
}

TEST(VtkXmlReader, PixelsBecomeQuads) {
  const MeshData d = read_vtk_xml(two_quads("0 1 3 4  1 2 4 5", "8 8"), "p.vtu");
  EXPECT_EQ(d.cells, ids({0, 1, 4, 3, 1, 2, 5, 4}));
}

}  // namespace
}  // namespace hexadapt::io
