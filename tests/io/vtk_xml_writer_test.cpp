#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/vtk_xml.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

MeshData write_and_read(const MeshData& d, bool vts, const WriteOptions& options) {
  const std::string path = test::temp_path(vts ? "w.vts" : "w.vtu");
  if (vts)
    write_vts(d, path, options);
  else
    write_vtu(d, path, options);
  MeshData back = read_vtk_xml(test::read_text(path), path);
  std::filesystem::remove(path);
  return back;
}

// Keys and values that an XML comment cannot hold as they are.
MeshData awkward_metadata_mesh() {
  MeshData d = test::sample_mesh(2, true);
  d.metadata = {{"tool", "hexadapt-test"},
                {"command", "hexadapt-overlay in.vtu -o out.vtu --threads 2 --"},
                {"lines", "first\nsecond\r\nthird\n"},
                {"markup", "a<b & c>d <AppendedData encoding=\"raw\"> ]]> <!-- x -->"},
                {"dashes", "-"},
                {"", "---"},
                {"key: with colon", "value: with colon"},
                {"back\\slash \\n", std::string("nul\0, bell\a, tab\t, \xC3\xA9, \xFF", 24)},
                {"empty", ""}};
  return d;
}

// The text of the comments before <VTKFile>, parsed by pugixml.
std::vector<std::string> leading_comments(const std::string& file_text) {
  const std::string prolog = file_text.substr(0, file_text.find("<VTKFile")) + "<VTKFile/>";
  pugi::xml_document doc;
  const pugi::xml_parse_result ok =
      doc.load_string(prolog.c_str(), pugi::parse_default | pugi::parse_comments);
  EXPECT_TRUE(ok) << ok.description() << " at " << ok.offset;
  std::vector<std::string> out;
  for (const pugi::xml_node c : doc.children())
    if (c.type() == pugi::node_comment) out.emplace_back(c.value());
  return out;
}

TEST(VtkXmlWriter, MetadataWithAwkwardCharactersRoundTrips) {
  const MeshData d = awkward_metadata_mesh();
  for (bool vts : {false, true}) {
    const MeshData back = write_and_read(d, vts, {});
    EXPECT_EQ(back.metadata, d.metadata) << (vts ? "vts" : "vtu");
  }
}

TEST(VtkXmlWriter, MetadataIsOneValidCommentAndNoStringArray) {
  const MeshData d = awkward_metadata_mesh();
  const std::string path = test::temp_path("meta.vtu");
  write_vtu(d, path);
  const std::string text = test::read_text(path);
  std::filesystem::remove(path);
  EXPECT_EQ(text.find("type=\"String\""), std::string::npos);
  EXPECT_EQ(text.find("<FieldData"), std::string::npos);
  EXPECT_EQ(text.find("<AppendedData"), text.rfind("<AppendedData"));
  const std::vector<std::string> comments = leading_comments(text);
  ASSERT_EQ(comments.size(), 1u);
  const std::string& c = comments[0];
  EXPECT_EQ(c.find("--"), std::string::npos);
  EXPECT_NE(c.back(), '-');
  // Readable by a person: plain entries stay plain, one line per entry.
  EXPECT_NE(c.find("\ntool: hexadapt-test\n"), std::string::npos) << c;
  EXPECT_NE(c.find("\nlines: first\\nsecond\\x0D\\nthird\\n\n"), std::string::npos) << c;
  EXPECT_NE(c.find("a\\x3Cb & c>d"), std::string::npos) << c;
  EXPECT_NE(c.find("\xC3\xA9"), std::string::npos) << c;  // valid UTF-8 is kept
  EXPECT_NE(c.find("\\xFF"), std::string::npos) << c;     // a stray byte is escaped
  std::size_t lines = 0;
  for (char ch : c) lines += ch == '\n';
  EXPECT_EQ(lines, 1 + d.metadata.size());
}

// The strings of a String field-data array written as ascii character codes, each ended by 0.
std::vector<std::string> string_field(const std::string& file_text, const std::string& name) {
  const std::string head = "<DataArray type=\"String\" Name=\"" + name + "\"";
  const std::size_t at = file_text.find(head);
  if (at == std::string::npos) return {};
  const std::size_t from = file_text.find('>', at) + 1;
  std::istringstream codes(file_text.substr(from, file_text.find('<', from) - from));
  std::vector<std::string> out(1);
  for (int c = 0; codes >> c;)
    if (c == 0)
      out.emplace_back();
    else
      out.back() += static_cast<char>(c);
  out.pop_back();
  return out;
}

// A file made by a second tool from the first one's, with a command an XML comment cannot
// hold as it is.
MeshData two_commands_mesh() {
  MeshData d = test::sample_mesh(2, false);
  d.metadata = {{"hexadapt_tool", "hexadapt-generate"},
                {"hexadapt_command", "hexadapt-generate disk -o in.vtu"},
                {"hexadapt_tool", "hexadapt-adapt"},
                {"hexadapt_command",
                 "hexadapt-adapt in.vtu --model m.vtk -o 'out dir/a.vtu' --threshold -0.5"}};
  return d;
}

TEST(VtkXmlWriter, CommandIsExactInFieldDataAndReadsBackOnce) {
  const MeshData d = two_commands_mesh();
  for (bool vts : {false, true}) {
    const std::string path = test::temp_path(vts ? "cmd.vts" : "cmd.vtu");
    if (vts)
      write_vts(d, path);
    else
      write_vtu(d, path);
    const std::string text = test::read_text(path);
    std::filesystem::remove(path);
    // The file's own command, as typed: "--" and all (the comment escapes it).
    EXPECT_EQ(string_field(text, "hexadapt_command"),
              std::vector<std::string>{d.metadata.back().second});
    EXPECT_NE(text.find("-\\x2Dmodel"), std::string::npos);
    // Read back: the entries of the comment, the command not a second time.
    EXPECT_EQ(read_vtk_xml(text, path).metadata, d.metadata);
    // A file that lost the comment (saved again by ParaView) still has the command.
    const std::size_t end = text.find("-->");
    ASSERT_NE(end, std::string::npos);
    const std::string no_comment = text.substr(0, text.find("<!--")) + text.substr(end + 3);
    EXPECT_EQ(read_vtk_xml(no_comment, path).metadata,
              (std::vector<std::pair<std::string, std::string>>{
                  {"hexadapt_command", d.metadata.back().second}}));
  }
}

TEST(VtkXmlWriter, NoStringFieldsLeavesTheCommandToTheComment) {
  MeshData d = two_commands_mesh();
  d.metadata.emplace_back("materials", "left,right");
  WriteOptions o;
  o.string_fields = false;
  const std::string path = test::temp_path("nostrings.vtu");
  write_vtu(d, path, o);
  const std::string text = test::read_text(path);
  std::filesystem::remove(path);
  EXPECT_EQ(text.find("type=\"String\""), std::string::npos);
  EXPECT_EQ(text.find("<FieldData"), std::string::npos);
  EXPECT_EQ(read_vtk_xml(text, path).metadata, d.metadata);
  write_vtu(d, path);  // both String arrays, in one FieldData
  const std::string both = test::read_text(path);
  std::filesystem::remove(path);
  EXPECT_EQ(both.find("<FieldData"), both.rfind("<FieldData"));
  EXPECT_EQ(string_field(both, "material_names"), (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(string_field(both, "hexadapt_command").size(), 1u);
}

TEST(VtkXmlWriter, MaterialNamesKeepTheirCommas) {
  MeshData d = test::sample_mesh(2, false);
  const std::vector<std::string> names{"air", "Volume Fraction for Body, Nose", "a\\b"};
  d.metadata = {{"hexadapt_materials", join_material_names(names)}};
  const std::string path = test::temp_path("names.vtu");
  write_vtu(d, path);
  const std::string text = test::read_text(path);
  std::filesystem::remove(path);
  EXPECT_EQ(string_field(text, "material_names"), names);
}

TEST(VtkXmlWriter, NoMetadataNoComment) {
  MeshData d = test::sample_mesh(2, false);
  d.metadata.clear();
  const std::string path = test::temp_path("nometa.vtu");
  write_vtu(d, path);
  const std::string text = test::read_text(path);
  EXPECT_EQ(text.find("<!--"), std::string::npos);
  EXPECT_TRUE(read_vtk_xml(text, path).metadata.empty());
  std::filesystem::remove(path);
}

TEST(VtkXmlWriter, VtuRoundTripsHexesAndQuadsCompressedOrNot) {
  for (bool hexes : {true, false})
    for (bool compress : {true, false}) {
      const MeshData d = test::sample_mesh(5, hexes);
      WriteOptions o;
      o.compress = compress;
      o.compress_above = 100;
      MeshData back = write_and_read(d, false, o);
      back.structured_cells = d.structured_cells;  // a .vtu is unstructured
      test::expect_same(d, back);
    }
}

TEST(VtkXmlWriter, VtsRoundTripsStructuredData) {
  for (bool hexes : {true, false}) {
    const MeshData d = test::sample_mesh(4, hexes);
    const MeshData back = write_and_read(d, true, {});
    test::expect_same(d, back);
    EXPECT_EQ(back.structured_cells, d.structured_cells);
  }
}

TEST(VtkXmlWriter, VtsRefusesUnstructuredCells) {
  MeshData d = test::sample_mesh(2, true);
  std::swap(d.cells[0], d.cells[1]);
  EXPECT_THROW(write_vts(d, test::temp_path("bad.vts")), OptionError);
  d.structured_cells = {0, 0, 0};
  EXPECT_THROW(write_vts(d, test::temp_path("bad.vts")), OptionError);
}

TEST(VtkXmlWriter, CompressionIsDeclaredOnlyWhenSomeArrayIsLarge) {
  const MeshData d = test::sample_mesh(3, true);
  const std::string path = test::temp_path("c.vtu");
  WriteOptions o;
  o.compress_above = 1 << 20;
  write_vtu(d, path, o);
  EXPECT_EQ(test::read_text(path).find("compressor"), std::string::npos);
  o.compress_above = 64;
  write_vtu(d, path, o);
  const std::string compressed = test::read_text(path);
  EXPECT_NE(compressed.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  test::expect_same(d, read_vtk_xml(compressed, path));
  std::filesystem::remove(path);
}

TEST(VtkXmlWriter, BytesDoNotDependOnTheThreadCount) {
  const MeshData d = test::sample_mesh(24, true);  // arrays of many zlib blocks
  const std::string path = test::temp_path("t.vtu");
  std::string first;
  for (int threads : {1, 2, 3}) {
    set_threads(threads);
    write_vtu(d, path, {});
    const std::string bytes = test::read_text(path);
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << threads << " threads";
    test::expect_same(d, read_vtk_xml(bytes, path));
  }
  set_threads(0);
  std::filesystem::remove(path);
}

TEST(VtkXmlWriter, IntegerArraysAreRoundedAndClampedToTheirType) {
  MeshData d = test::sample_mesh(1, false);
  DataArray a;
  a.name = "small";
  a.type = ScalarType::uint8;
  a.values = {300.0};
  d.set_cell_array(a);
  a.name = "rounded";
  a.type = ScalarType::int32;
  a.values = {-2.6};
  d.set_cell_array(a);
  const MeshData back = write_and_read(d, false, {});
  EXPECT_EQ(back.find_cell_array("small")->values, std::vector<double>{255.0});
  EXPECT_EQ(back.find_cell_array("rounded")->values, std::vector<double>{-3.0});
}

TEST(VtkXmlWriter, FailedWriteIsAnIoErrorAndLeavesNoFile) {
  const MeshData d = test::sample_mesh(1, true);
  EXPECT_THROW(write_vtu(d, "/nonexistent-dir/x.vtu"), IoError);
}

}  // namespace
}  // namespace hexadapt::io
