#include "vtk_xml_encode.h"

#include <zlib.h>

#include <cstdint>
#include <cstring>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "vtk_xml_scalar.h"

namespace hexadapt::io::detail {

namespace {

// Fast levels keep writing near disk speed; mesh data compresses well even at level 1.
constexpr int zlib_level = 1;

void put_word(std::vector<unsigned char>& out, std::uint64_t v) {
  unsigned char b[8];
  std::memcpy(b, &v, 8);
  out.insert(out.end(), b, b + 8);
}

std::vector<unsigned char> encode_plain(const OutArray& a, std::size_t n_bytes) {
  std::vector<unsigned char> out;
  out.reserve(8 + n_bytes);
  put_word(out, n_bytes);
  out.resize(8 + n_bytes);
  a.fill(0, a.n_values, out.data() + 8);
  return out;
}

std::vector<unsigned char> encode_zlib(const OutArray& a, std::size_t n_bytes, int level) {
  const std::size_t size = scalar_size(a.type);
  const std::size_t per_block = zlib_block_size / size;
  const std::size_t n_blocks = (n_bytes + zlib_block_size - 1) / zlib_block_size;
  std::vector<std::vector<unsigned char>> blocks(n_blocks);
  std::vector<char> ok(n_blocks, 0);
  for_blocks(static_cast<std::int64_t>(n_blocks), [&](std::int64_t b) {
    const auto k = static_cast<std::size_t>(b);
    const std::size_t first = k * per_block;
    const std::size_t count = std::min(per_block, a.n_values - first);
    std::vector<unsigned char> raw(count * size);
    a.fill(first, count, raw.data());
    uLongf n = compressBound(static_cast<uLong>(raw.size()));
    blocks[k].resize(n);
    ok[k] =
        compress2(blocks[k].data(), &n, raw.data(), static_cast<uLong>(raw.size()), level) == Z_OK;
    blocks[k].resize(n);
  });
  for (char c : ok)
    if (!c) throw InternalError("zlib failed to compress array '" + a.name + "'");
  std::vector<unsigned char> out;
  std::size_t total = 8 * (3 + n_blocks);
  for (const auto& b : blocks) total += b.size();
  out.reserve(total);
  put_word(out, n_blocks);
  put_word(out, zlib_block_size);
  put_word(out, n_bytes % zlib_block_size);  // 0: the last block is full
  for (const auto& b : blocks) put_word(out, b.size());
  for (const auto& b : blocks) out.insert(out.end(), b.begin(), b.end());
  return out;
}

}  // namespace

std::vector<unsigned char> encode_array(const OutArray& a, const Encoding& encoding) {
  const std::size_t n_bytes = a.n_values * scalar_size(a.type);
  if (!encoding.zlib) return encode_plain(a, n_bytes);
  return encode_zlib(a, n_bytes, n_bytes > encoding.compress_above ? zlib_level : 0);
}

}  // namespace hexadapt::io::detail
