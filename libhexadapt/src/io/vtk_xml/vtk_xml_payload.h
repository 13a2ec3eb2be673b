// Private to the VTK XML reader: the binary payload of one DataArray, i.e. VTK's header
// (byte count, or the block table of compressed data) followed by the data, read from raw
// appended bytes or from base64 text. Every size read from a header is checked against the
// bytes that remain before anything is allocated.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vtk_xml_base64.h"
#include "vtk_xml_decompress.h"

namespace hexadapt::io::detail {

/// The file-wide settings of the VTKFile element.
struct BinaryLayout {
  bool header64 = false;                     ///< header_type="UInt64" (else UInt32)
  bool big_endian = false;                   ///< byte_order="BigEndian"
  Compressor compressor = Compressor::none;  ///< the compressor attribute
};

/// Bytes of an array in the file's byte order: either a view into the file or owned.
struct Payload {
  std::vector<unsigned char> owned;
  const unsigned char* data = nullptr;
  std::size_t size = 0;
};

/// Sequential reader over raw bytes or base64 text. Errors name the file byte offset.
class ByteReader {
 public:
  static ByteReader raw(std::string_view bytes, std::size_t file_offset, const std::string& file);
  static ByteReader base64(std::string_view text, std::size_t file_offset, const std::string& file);
  /// The next n bytes. Throws InputError when fewer remain.
  Payload take(std::size_t n, const std::string& what);
  std::size_t max_remaining() const;
  std::size_t file_offset() const;
  const std::string& file() const { return file_; }

 private:
  ByteReader(std::string_view bytes, std::size_t file_offset, const std::string& file, bool b64);
  std::string_view raw_;
  std::size_t pos_ = 0, file_offset_;
  std::string file_;
  std::optional<Base64Reader> b64_;
};

/// Reads the header and data of one array holding exactly `expected_bytes` bytes (any size
/// the header gives when nullopt); decompresses zlib, LZ4 or LZMA blocks in parallel. `what`
/// names the array in errors. With `allocate`, compressed data is decompressed into the
/// memory it returns for the size (called once the sizes are checked) rather than into a new
/// buffer.
Payload read_payload(ByteReader& in, const BinaryLayout& layout,
                     std::optional<std::size_t> expected_bytes, const std::string& what,
                     const std::function<unsigned char*(std::size_t)>& allocate = {});

}  // namespace hexadapt::io::detail
