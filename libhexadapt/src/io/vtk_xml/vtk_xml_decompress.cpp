#include "vtk_xml_decompress.h"

#include <lz4.h>
#include <lzma.h>
#include <zlib.h>

#include <limits>

namespace hexadapt::io::detail {

namespace {

// An .xz stream names the dictionary its decoder allocates: VTK's levels need at most 64 MiB
// (level 9); a stream asking more than this is refused rather than obeyed.
constexpr std::uint64_t lzma_memory_limit = std::uint64_t{256} << 20;

bool inflate_zlib(const unsigned char* src, std::uint64_t n, unsigned char* dst,
                  std::uint64_t size) {
  if (n > std::numeric_limits<uLong>::max() || size > std::numeric_limits<uLongf>::max())
    return false;
  uLongf out = static_cast<uLongf>(size);
  const int rc = uncompress(dst, &out, src, static_cast<uLong>(n));
  return rc == Z_OK && out == size;
}

bool decode_lz4(const unsigned char* src, std::uint64_t n, unsigned char* dst, std::uint64_t size) {
  constexpr auto int_max = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
  if (n > int_max || size > int_max) return false;
  const int out =
      LZ4_decompress_safe(reinterpret_cast<const char*>(src), reinterpret_cast<char*>(dst),
                          static_cast<int>(n), static_cast<int>(size));
  return out >= 0 && static_cast<std::uint64_t>(out) == size;
}

bool decode_lzma(const unsigned char* src, std::uint64_t n, unsigned char* dst,
                 std::uint64_t size) {
  std::uint64_t memory = lzma_memory_limit;
  std::size_t in_pos = 0, out_pos = 0;
  const lzma_ret rc =
      lzma_stream_buffer_decode(&memory, 0, nullptr, src, &in_pos, static_cast<std::size_t>(n), dst,
                                &out_pos, static_cast<std::size_t>(size));
  return rc == LZMA_OK && out_pos == size && in_pos == n;
}

}  // namespace

std::optional<Compressor> compressor_of(const std::string& name) {
  if (name.empty()) return Compressor::none;
  if (name == "vtkZLibDataCompressor") return Compressor::zlib;
  if (name == "vtkLZ4DataCompressor") return Compressor::lz4;
  if (name == "vtkLZMADataCompressor") return Compressor::lzma;
  return std::nullopt;
}

const char* compressor_name(Compressor c) {
  switch (c) {
    case Compressor::zlib:
      return "zlib";
    case Compressor::lz4:
      return "LZ4";
    case Compressor::lzma:
      return "LZMA";
    default:
      return "uncompressed";
  }
}

std::uint64_t max_expansion(Compressor c) {
  // zlib: about 1032 (deflate's longest match per bit); LZ4: 255 bytes per extra length byte;
  // LZMA: about 7000 measured on zeros, bounded generously.
  switch (c) {
    case Compressor::zlib:
      return 1032;
    case Compressor::lz4:
      return 256;
    case Compressor::lzma:
      return std::uint64_t{1} << 14;
    default:
      return 1;
  }
}

bool decompress_block(Compressor c, const unsigned char* src, std::uint64_t n, unsigned char* dst,
                      std::uint64_t size) {
  switch (c) {
    case Compressor::zlib:
      return inflate_zlib(src, n, dst, size);
    case Compressor::lz4:
      return decode_lz4(src, n, dst, size);
    case Compressor::lzma:
      return decode_lzma(src, n, dst, size);
    default:
      return false;
  }
}

}  // namespace hexadapt::io::detail
