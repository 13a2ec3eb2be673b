// Private to the VTK XML writer: one array as it appears in raw appended data, i.e. a UInt64
// header and the values, either plain or as zlib blocks in VTK's blocked layout (block
// count, block size, last block size, compressed sizes). Blocks are compressed in parallel
// and independently, so the bytes do not depend on the thread count.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io::detail {

/// An array to write, produced piecewise so that no converted copy of it is needed.
struct OutArray {
  std::string name;
  int n_components = 1;
  ScalarType type = ScalarType::float64;
  std::size_t n_values = 0;
  /// Packs values [first, first + count) as `type`, native byte order, into out.
  std::function<void(std::size_t first, std::size_t count, unsigned char* out)> fill;
};

/// How the arrays of one file are encoded.
struct Encoding {
  bool zlib = false;               ///< the file declares vtkZLibDataCompressor
  std::size_t compress_above = 0;  ///< arrays of at most this many bytes are stored uncompressed
};

/// Size of VTK's default zlib blocks; every scalar size divides it.
inline constexpr std::size_t zlib_block_size = 1 << 15;

/// Header and data bytes of one array in appended data.
std::vector<unsigned char> encode_array(const OutArray& a, const Encoding& encoding);

}  // namespace hexadapt::io::detail
