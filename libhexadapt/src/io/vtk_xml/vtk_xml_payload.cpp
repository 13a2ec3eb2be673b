#include "vtk_xml_payload.h"

#include <algorithm>
#include <cstring>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "vtk_xml_scalar.h"

namespace hexadapt::io::detail {

namespace {

std::uint64_t header_word(const unsigned char* p, const BinaryLayout& layout) {
  const bool swap = layout.big_endian == native_little_endian();
  std::int64_t v = 0;
  if (layout.header64) {
    std::uint64_t u;
    std::memcpy(&u, p, 8);
    if (swap) {
      unsigned char b[8];
      std::memcpy(b, p, 8);
      std::reverse(b, b + 8);
      std::memcpy(&u, b, 8);
    }
    return u;
  }
  unpack(p, ScalarType::uint32, swap, 1, &v);
  return static_cast<std::uint64_t>(v);
}

std::string bytes_text(std::uint64_t n) {
  return std::to_string(n) + " bytes";
}

struct BlockTable {
  std::uint64_t n_blocks = 0, block_size = 0, last_size = 0, total = 0;
  std::vector<std::uint64_t> compressed;  ///< compressed size of each block
  std::uint64_t compressed_total = 0;
};

BlockTable read_block_table(ByteReader& in, const BinaryLayout& layout, const std::string& what) {
  const std::size_t w = layout.header64 ? 8 : 4;
  const std::size_t at = in.file_offset();
  const std::string where = "byte " + std::to_string(at);
  BlockTable t;
  Payload first = in.take(3 * w, what + " (compression header)");
  t.n_blocks = header_word(first.data, layout);
  t.block_size = header_word(first.data + w, layout);
  t.last_size = header_word(first.data + 2 * w, layout);
  if (t.n_blocks > in.max_remaining() / w)
    throw InputError(in.file(), where,
                     what + ": compression header claims " + std::to_string(t.n_blocks) +
                         " blocks, more than the file holds (truncated or corrupt)");
  if (t.n_blocks > 0 && (t.block_size == 0 || t.last_size > t.block_size))
    throw InputError(in.file(), where,
                     what + ": inconsistent block sizes (block " + std::to_string(t.block_size) +
                         ", last block " + std::to_string(t.last_size) + ")");
  Payload sizes = in.take(static_cast<std::size_t>(t.n_blocks) * w, what + " (block sizes)");
  t.compressed.resize(t.n_blocks);
  for (std::size_t k = 0; k < t.n_blocks; ++k) {
    t.compressed[k] = header_word(sizes.data + k * w, layout);
    if (t.compressed[k] > in.max_remaining() ||
        t.compressed_total + t.compressed[k] > in.max_remaining())
      throw InputError(in.file(), where,
                       what +
                           ": compressed blocks need more bytes than the file holds "
                           "(truncated or corrupt)");
    t.compressed_total += t.compressed[k];
  }
  // Each block's size is bounded by the format's ratio first, so the total cannot overflow.
  const std::uint64_t last = t.last_size == 0 ? t.block_size : t.last_size;
  const std::uint64_t ratio = max_expansion(layout.compressor);
  for (std::size_t k = 0; k < t.n_blocks; ++k) {
    const std::uint64_t size = k + 1 == t.n_blocks ? last : t.block_size;
    if (size > t.compressed[k] * ratio + 64)
      throw InputError(in.file(), where,
                       what + ": block " + std::to_string(k) + " claims " + bytes_text(size) +
                           " from " + bytes_text(t.compressed[k]) + " of " +
                           compressor_name(layout.compressor) + " data");
    t.total += size;
  }
  return t;
}

Payload read_compressed(ByteReader& in, const BinaryLayout& layout,
                        std::optional<std::size_t> expected_bytes, const std::string& what,
                        const std::function<unsigned char*(std::size_t)>& allocate) {
  const std::size_t at = in.file_offset();
  const BlockTable t = read_block_table(in, layout, what);
  const std::size_t expected = expected_bytes.value_or(static_cast<std::size_t>(t.total));
  if (t.total != expected)
    throw InputError(in.file(), "byte " + std::to_string(at),
                     what + ": compressed data holds " + bytes_text(t.total) + ", expected " +
                         bytes_text(expected));
  const std::size_t data_at = in.file_offset();
  Payload packed = in.take(static_cast<std::size_t>(t.compressed_total),
                           what + " (" + compressor_name(layout.compressor) + " blocks)");
  Payload out;
  unsigned char* into = nullptr;
  if (allocate) {
    into = allocate(expected);
  } else {
    out.owned.resize(expected);
    into = out.owned.data();
  }
  std::vector<std::size_t> start(t.n_blocks + 1, 0);
  for (std::size_t k = 0; k < t.n_blocks; ++k) start[k + 1] = start[k] + t.compressed[k];
  std::vector<char> ok(t.n_blocks, 0);
  for_blocks(static_cast<std::int64_t>(t.n_blocks), [&](std::int64_t b) {
    const auto k = static_cast<std::size_t>(b);
    const std::uint64_t size = std::min<std::uint64_t>(t.block_size, expected - k * t.block_size);
    ok[k] = decompress_block(layout.compressor, packed.data + start[k], t.compressed[k],
                             into + k * t.block_size, size);
  });
  const auto bad = static_cast<std::size_t>(std::find(ok.begin(), ok.end(), 0) - ok.begin());
  if (bad < t.n_blocks)
    throw InputError(in.file(), "byte " + std::to_string(data_at + start[bad]),
                     what + ": " + compressor_name(layout.compressor) + " block " +
                         std::to_string(bad) +
                         " is corrupt or does not decompress to its declared size");
  out.data = into;
  out.size = expected;
  return out;
}

}  // namespace

ByteReader::ByteReader(std::string_view bytes, std::size_t file_offset, const std::string& file,
                       bool b64)
    : raw_(bytes), file_offset_(file_offset), file_(file) {
  if (b64) b64_.emplace(bytes, file_offset, file);
}

ByteReader ByteReader::raw(std::string_view bytes, std::size_t file_offset,
                           const std::string& file) {
  return ByteReader(bytes, file_offset, file, false);
}
ByteReader ByteReader::base64(std::string_view text, std::size_t file_offset,
                              const std::string& file) {
  return ByteReader(text, file_offset, file, true);
}

std::size_t ByteReader::max_remaining() const {
  return b64_ ? b64_->max_remaining() : raw_.size() - pos_;
}
std::size_t ByteReader::file_offset() const {
  return b64_ ? b64_->file_offset() : file_offset_ + pos_;
}

Payload ByteReader::take(std::size_t n, const std::string& what) {
  Payload p;
  if (b64_) {
    b64_->read(n, p.owned, what);
    p.data = p.owned.data();
  } else {
    if (n > raw_.size() - pos_)
      throw InputError(file_, "byte " + std::to_string(file_offset()),
                       what + ": needs " + bytes_text(n) + ", only " +
                           bytes_text(raw_.size() - pos_) + " remain (truncated file?)");
    p.data = reinterpret_cast<const unsigned char*>(raw_.data() + pos_);
    pos_ += n;
  }
  p.size = n;
  return p;
}

Payload read_payload(ByteReader& in, const BinaryLayout& layout,
                     std::optional<std::size_t> expected_bytes, const std::string& what,
                     const std::function<unsigned char*(std::size_t)>& allocate) {
  if (layout.compressor != Compressor::none)
    return read_compressed(in, layout, expected_bytes, what, allocate);
  const std::size_t at = in.file_offset();
  const Payload head = in.take(layout.header64 ? 8 : 4, what + " (size header)");
  const std::uint64_t n = header_word(head.data, layout);
  if (expected_bytes && n != *expected_bytes)
    throw InputError(
        in.file(), "byte " + std::to_string(at),
        what + ": header gives " + bytes_text(n) + ", expected " + bytes_text(*expected_bytes));
  if (n > in.max_remaining())
    throw InputError(in.file(), "byte " + std::to_string(at),
                     what + ": header gives " + bytes_text(n) + ", only " +
                         bytes_text(in.max_remaining()) + " remain (truncated file?)");
  return in.take(static_cast<std::size_t>(n), what);
}

}  // namespace hexadapt::io::detail
