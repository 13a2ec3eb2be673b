// LZ4 and LZMA blocks in VTK XML files (vtk_xml_decompress.h): files written by VTK read as
// their ascii twin, and corrupt or lying blocks are InputErrors naming the compressor.
#include <gtest/gtest.h>

#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

std::string testdata(const std::string& name) {
  return test::read_text(std::string(HEXADAPT_TESTDATA) + "/" + name);
}

TEST(VtkXmlCompressors, Lz4AndLzmaFilesOfVtkReadAsTheirAsciiTwin) {
  const MeshData ascii = read_vtk_xml(testdata("two_hexes_vtk_ascii.vtu"), "ascii.vtu");
  test::expect_same(read_vtk_xml(testdata("two_hexes_vtk_lz4.vtu"), "lz4.vtu"), ascii);
  test::expect_same(read_vtk_xml(testdata("two_hexes_vtk_lzma_uint64.vtu"), "lzma.vtu"), ascii);
}

TEST(VtkXmlCompressors, ACorruptBlockNamesItsCompressor) {
  for (const auto& [file, name] : {std::pair{"two_hexes_vtk_lz4.vtu", "LZ4"},
                                   std::pair{"two_hexes_vtk_lzma_uint64.vtu", "LZMA"}}) {
    SCOPED_TRACE(file);
    std::string s = testdata(file);
    // The first array's blocks start after its header: 4 words of 4 (LZ4) or 8 (LZMA) bytes.
    const std::size_t data = test::appended_start(s) + (std::string(name) == "LZ4" ? 16 : 32);
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
  const std::size_t at = test::appended_start(s);
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
