// Hand-made malformed VTK XML files: each must give an InputError naming the file, the
// place and what was expected. No crash, no hang, no allocation driven by a lying header.
#include <gtest/gtest.h>

#include <cstring>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

const std::string ascii_quad = R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt32">
  <UnstructuredGrid>
    <Piece NumberOfPoints="4" NumberOfCells="1">
      <CellData><DataArray type="Float64" Name="vf" format="ascii">0.5</DataArray></CellData>
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 1 1 0 0 1 0</DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">9</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";

const std::string ascii_image = R"(<VTKFile type="ImageData">
  <ImageData WholeExtent="0 2 0 2 0 2" Origin="0 0 0" Spacing="1 1 1">
    <Piece Extent="0 2 0 2 0 2"></Piece>
  </ImageData>
</VTKFile>)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  if (at == std::string::npos) throw std::logic_error("test pattern not found: " + from);
  return s.replace(at, from.size(), to);
}

// Our own writer's output for a small mesh, raw or zlib-compressed.
std::string written(bool compress) {
  const MeshData d = test::sample_mesh(3, true);
  const std::string path = test::temp_path(compress ? "mz.vtu" : "mr.vtu");
  WriteOptions o;
  o.compress = compress;
  o.compress_above = 0;
  write_vtu(d, path, o);
  std::string s = test::read_text(path);
  std::filesystem::remove(path);
  return s;
}

// Byte position of the first array's header (offset 0) in appended data.
std::string set_word(std::string s, std::size_t word, std::uint64_t value) {
  std::memcpy(&s[test::appended_start(s) + 8 * word], &value, 8);
  return s;
}

std::uint64_t get_word(const std::string& s, std::size_t word) {
  std::uint64_t v;
  std::memcpy(&v, &s[test::appended_start(s) + 8 * word], 8);
  return v;
}

// An inline base64 points array with the given text.
std::string inline_points(const std::string& text) {
  return replace(ascii_quad, R"(format="ascii">0 0 0 1 0 0 1 1 0 0 1 0)",
                 "format=\"binary\">" + text);
}

struct Case {
  const char* name;
  std::string content;
  const char* expected;  ///< a part of the message
};

std::vector<Case> cases() {
  const std::string raw = written(false), zlib = written(true);
  const std::uint64_t n_blocks = get_word(zlib, 0);
  std::string corrupt = zlib;
  corrupt[test::appended_start(zlib) + 8 * (3 + n_blocks) + 2] ^= 0x55;
  return {
      {"not XML", "hello", "malformed XML"},
      {"truncated XML", ascii_quad.substr(0, 300), "malformed XML"},
      {"no VTKFile", "<Other/>", "no <VTKFile>"},
      {"unsupported data set",
       replace(ascii_quad, "type=\"UnstructuredGrid\"", "type=\"PolyData\""), "PolyData"},
      {"no data set element",
       replace(ascii_quad, "type=\"UnstructuredGrid\"", "type=\"StructuredGrid\""),
       "no <StructuredGrid>"},
      {"no piece", replace(replace(ascii_quad, "<Piece ", "<Peace "), "</Piece>", "</Peace>"),
       "no <Piece>"},
      {"two pieces", replace(ascii_quad, "</Piece>", "</Piece><Piece/>"), "multi-piece"},
      {"no points", replace(replace(ascii_quad, "<Points>", "<Pts>"), "</Points>", "</Pts>"),
       "no <Points>"},
      {"no cells", replace(replace(ascii_quad, "<Cells>", "<Cls>"), "</Cells>", "</Cls>"),
       "no <Cells>"},
      {"no types", replace(ascii_quad, "Name=\"types\"", "Name=\"kinds\""), "named 'types'"},
      {"empty mesh", replace(ascii_quad, "NumberOfCells=\"1\"", "NumberOfCells=\"0\""),
       "empty mesh"},
      {"bad count", replace(ascii_quad, "NumberOfPoints=\"4\"", "NumberOfPoints=\"four\""),
       "NumberOfPoints"},
      {"too few values", replace(ascii_quad, "1 1 0 0 1 0<", "1 1 0 0 1<"),
       "expected 12 values, found 11"},
      {"too many values", replace(ascii_quad, ">0.5<", ">0.5 0.7<"), "more than the expected 1"},
      {"bad number", replace(ascii_quad, ">0.5<", ">0.5x<"), "not a valid Float64"},
      {"unknown type",
       replace(ascii_quad, "type=\"Float64\" Name=\"vf\"", "type=\"Float16\" Name=\"vf\""),
       "Float16"},
      {"unknown format",
       replace(ascii_quad, "Name=\"vf\" format=\"ascii\"", "Name=\"vf\" format=\"hex\""),
       "format 'hex'"},
      {"wrong components",
       replace(ascii_quad, "NumberOfComponents=\"3\"", "NumberOfComponents=\"2\""),
       "expected 3 components"},
      {"triangle", replace(replace(ascii_quad, ">9<", ">5<"), ">4<", ">4<"),
       "unsupported VTK cell type 5"},
      {"cell type wraps", replace(ascii_quad, ">9<", ">4294967305<"),
       "4294967305 is not a VTK cell type"},
      {"node out of range", replace(ascii_quad, ">0 1 2 3<", ">0 1 2 7<"), "out of range"},
      {"wrong node count", replace(ascii_quad, ">4<", ">3<"), "more than the expected 3"},
      {"wrong node count in the types",
       replace(replace(ascii_quad, ">4<", ">3<"), ">0 1 2 3<", ">0 1 2<"),
       "has 3 nodes, expected 4"},
      {"offsets decrease",
       replace(replace(replace(ascii_quad, "NumberOfCells=\"1\"", "NumberOfCells=\"2\""), ">4<",
                       ">4 2<"),
               ">9<", ">9 9<")
           .replace(0, 0, ""),
       "smaller than the previous"},
      {"mixed 2D and 3D",
       replace(replace(replace(replace(ascii_quad, "NumberOfCells=\"1\"", "NumberOfCells=\"2\""),
                               ">4<", ">4 12<"),
                       ">9<", ">9 12<"),
               ">0 1 2 3<", ">0 1 2 3 0 1 2 3 0 1 2 3<"),
       "mixes 2D and 3D"},
      {"bad header_type", replace(ascii_quad, "header_type=\"UInt32\"", "header_type=\"UInt16\""),
       "header_type 'UInt16'"},
      {"bad byte_order",
       replace(ascii_quad, "byte_order=\"LittleEndian\"", "byte_order=\"Middle\""),
       "byte_order 'Middle'"},
      {"unknown compressor",
       replace(ascii_quad, "header_type=", "compressor=\"vtkZstdDataCompressor\" header_type="),
       "vtkZstdDataCompressor"},
      {"invalid base64", inline_points("AAAA@@@@"), "invalid base64"},
      {"short base64", inline_points("YAAAAA=="), "truncated"},
      {"base64 size header lies", inline_points("AAAAAA=="), "header gives 0 bytes, expected 96"},
      {"image extent reversed",
       replace(ascii_image, "Piece Extent=\"0 2 0 2 0 2\"", "Piece Extent=\"0 2 2 0 0 2\""),
       "min <= max"},
      {"image too flat",
       replace(ascii_image, "Piece Extent=\"0 2 0 2 0 2\"", "Piece Extent=\"0 2 0 0 0 0\""),
       "single row"},
      {"image huge",
       replace(ascii_image, "Piece Extent=\"0 2 0 2 0 2\"",
               "Piece Extent=\"0 2000000 0 2000000 0 2\""),
       "too many points"},
      {"image array short",
       replace(ascii_image, "<Piece Extent=\"0 2 0 2 0 2\">",
               "<Piece Extent=\"0 2 0 2 0 2\"><CellData><DataArray type=\"Int8\" Name=\"m\" "
               "format=\"ascii\">1 2 3</DataArray></CellData>"),
       "expected 8 values"},
      {"appended truncated", raw.substr(0, test::appended_start(raw) + 40), "truncated"},
      {"appended cut at end", raw.substr(0, raw.size() - 200), "truncated"},
      {"no underscore", replace(raw, "\"raw\">_", "\"raw\">x"), "expected '_'"},
      {"offset beyond end", replace(raw, "offset=\"0\"", "offset=\"99999999\""), "beyond the end"},
      {"no appended data", raw.substr(0, raw.find("<AppendedData")) + "</VTKFile>",
       "no AppendedData"},
      {"size header lies", set_word(raw, 0, 1), "header gives 1 bytes"},
      {"size header huge", set_word(raw, 0, std::uint64_t(1) << 60), "header gives"},
      {"block count huge", set_word(zlib, 0, std::uint64_t(1) << 50), "more than the file holds"},
      {"last block too large", set_word(zlib, 2, get_word(zlib, 1) + 1),
       "inconsistent block sizes"},
      {"block size zero", set_word(zlib, 1, 0), "inconsistent block sizes"},
      {"compressed size huge", set_word(zlib, 3, std::uint64_t(1) << 40),
       "more bytes than the file holds"},
      {"block claims too much", set_word(set_word(zlib, 1, std::uint64_t(1) << 36), 2, 0),
       "claims"},
      {"total differs", set_word(zlib, 2, 8), "expected"},
      {"corrupt zlib block", corrupt, "zlib block 0"},
  };
}

TEST(VtkXmlMalformed, EveryCaseIsAnInputErrorWithFilePlaceAndExpectation) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    try {
      read_vtk_xml(c.content, "bad.vtu");
      ADD_FAILURE() << "no error for " << c.name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "bad.vtu");
      EXPECT_FALSE(e.where().empty());
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
    }
  }
}

TEST(VtkXmlMalformed, TheValidBasesRead) {
  EXPECT_EQ(read_vtk_xml(ascii_quad, "ok.vtu").n_cells(), 1);
  EXPECT_EQ(read_vtk_xml(ascii_image, "ok.vti").n_cells(), 8);
  EXPECT_EQ(read_vtk_xml(written(false), "ok.vtu").n_cells(), 27);
  EXPECT_EQ(read_vtk_xml(written(true), "ok.vtu").n_cells(), 27);
}

// Every prefix of a compressed file fails cleanly (or reads, for the complete file).
TEST(VtkXmlMalformed, EveryTruncationFailsCleanly) {
  const std::string zlib = written(true);
  const std::size_t data_end = zlib.rfind("</AppendedData>") - 3;  // before "\n  "
  for (std::size_t n = 0; n < data_end; n += 97) {
    try {
      read_vtk_xml(zlib.substr(0, n), "cut.vtu");
      ADD_FAILURE() << "read a file cut at " << n;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "cut.vtu");
    }
  }
}

}  // namespace
}  // namespace hexadapt::io
