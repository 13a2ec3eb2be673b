// LZ4 and LZMA blocks in VTK XML files (vtk_xml_decompress.h): files written by VTK read as
// their ascii twin, and corrupt or lying blocks are InputErrors naming the compressor.
#include <gtest/gtest.h>

#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"
#include "io/vtk_xml_test_util.h"

namespace hexadapt::io {
namespace {

std::string testdata(const std::string& name) {
  return test::read_text(std::string(HEXADAPT_TESTDATA) + "/" + name);
}

void expect_same(const MeshData& a, const MeshData& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.cells, b.cells);
  ASSERT_EQ(a.cell_data.size(), b.cell_data.size());
  for (std::size_t k = 0; k < a.cell_data.size(); ++k)
    EXPECT_EQ(a.cell_data[k].values, b.cell_data[k].values) << a.cell_data[k].name;
  ASSERT_EQ(a.point_data.size(), b.point_data.size());
  EXPECT_EQ(a.point_data[0].values, b.point_data[0].values);
}

// The first byte of the appended data (after the '_' marker).
std::size_t appended_start(const std::string& s) {
  return s.find('_', s.find("<AppendedData")) + 1;
}

TEST(VtkXmlCompressors, Lz4AndLzmaFilesOfVtkReadAsTheirAsciiTwin) {
  const MeshData ascii = read_vtk_xml(testdata("two_hexes_vtk_ascii.vtu"), "ascii.vtu");
  expect_same(read_vtk_xml(testdata("two_hexes_vtk_lz4.vtu"), "lz4.vtu"), ascii);
  expect_same(read_vtk_xml(testdata("two_hexes_vtk_lzma_uint64.vtu"), "lzma.vtu"), ascii);
}

TEST(VtkXmlCompressors, ACorruptBlockNamesItsCompressor) {
  for (const auto& [file, name] : {std::pair{"two_hexes_vtk_lz4.vtu", "LZ4"},
                                   std::pair{"two_hexes_vtk_lzma_uint64.vtu", "LZMA"}}) {
    SCOPED_TRACE(file);
    std::string s = testdata(file);
    // The first array's blocks start after its header: 4 words of 4 (LZ4) or 8 (LZMA) bytes.
    const std::size_t data = appended_start(s) + (std::string(name) == "LZ4" ? 16 : 32);
    for (std::size_t k = data; k < data + 6; ++k) s[k] = static_cast<char>(s[k] ^ 0x5a);
    try {
      read_vtk_xml(s, "bad.vtu");
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(e.message().find(std::string(name) + " block 0 is corrupt"), std::string::npos)
          << e.what();
    }
  }
}

TEST(VtkXmlCompressors, ABlockClaimingMoreThanLz4CanExpandIsALie) {
  std::string s = testdata("two_hexes_vtk_lz4.vtu");
  // Header words: blocks, block size, last block size, then the compressed sizes.
  const std::size_t at = appended_start(s);
  const std::uint32_t huge = 1u << 30;
  for (std::size_t b = 0; b < 4; ++b) {
    s[at + 4 + b] = static_cast<char>(huge >> (8 * b) & 0xff);
    s[at + 8 + b] = 0;
  }
  try {
    read_vtk_xml(s, "bad.vtu");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("of LZ4 data"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hexadapt::io
