#include "vtk_xml_base64.h"

#include <array>

#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

namespace {

constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr unsigned char whitespace = 64, padding = 65, invalid = 255;

constexpr std::array<unsigned char, 256> make_table() {
  std::array<unsigned char, 256> t{};
  for (auto& v : t) v = invalid;
  for (unsigned char k = 0; k < 64; ++k) t[static_cast<unsigned char>(alphabet[k])] = k;
  t[' '] = t['\n'] = t['\r'] = t['\t'] = whitespace;
  t['='] = padding;
  return t;
}
constexpr std::array<unsigned char, 256> table = make_table();

}  // namespace

std::string base64_encode(const unsigned char* bytes, std::size_t n) {
  std::string out;
  out.reserve((n + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const unsigned v = unsigned(bytes[i]) << 16 | unsigned(bytes[i + 1]) << 8 | bytes[i + 2];
    out += alphabet[v >> 18 & 63];
    out += alphabet[v >> 12 & 63];
    out += alphabet[v >> 6 & 63];
    out += alphabet[v & 63];
  }
  if (i < n) {
    const bool two = i + 1 < n;
    const unsigned v = unsigned(bytes[i]) << 16 | (two ? unsigned(bytes[i + 1]) << 8 : 0u);
    out += alphabet[v >> 18 & 63];
    out += alphabet[v >> 12 & 63];
    out += two ? alphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

Base64Reader::Base64Reader(std::string_view text, std::size_t file_offset, std::string file)
    : text_(text), file_offset_(file_offset), file_(std::move(file)) {}

// Decodes the next quantum (4 characters, or fewer at a padded or final end) into pending_.
bool Base64Reader::next_quantum(const std::string& what) {
  unsigned v = 0;
  int n_chars = 0, n_pad = 0;
  while (pos_ < text_.size() && n_chars + n_pad < 4) {
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    const unsigned char t = table[c];
    if (t == whitespace) {
      ++pos_;
      continue;
    }
    if (t == invalid || (t < 64 && n_pad > 0))
      throw InputError(file_, "byte " + std::to_string(file_offset()),
                       what + ": invalid base64 character (code " + std::to_string(c) + ")");
    ++pos_;
    if (t == padding) {
      ++n_pad;
    } else {
      v = v << 6 | t;
      ++n_chars;
    }
  }
  if (n_chars == 0 && n_pad == 0) return false;
  if (n_chars < 2 || (n_pad > 0 && n_chars + n_pad != 4))
    throw InputError(file_, "byte " + std::to_string(file_offset()),
                     what + ": incomplete base64 quantum");
  v <<= 6 * (4 - n_chars);
  pending_.clear();
  pending_pos_ = 0;
  pending_.push_back(static_cast<unsigned char>(v >> 16));
  if (n_chars >= 3) pending_.push_back(static_cast<unsigned char>(v >> 8 & 255));
  if (n_chars == 4) pending_.push_back(static_cast<unsigned char>(v & 255));
  return true;
}

void Base64Reader::read(std::size_t n, std::vector<unsigned char>& out, const std::string& what) {
  if (n > max_remaining())
    throw InputError(file_, "byte " + std::to_string(file_offset()),
                     what + ": needs " + std::to_string(n) +
                         " more bytes, the base64 text holds "
                         "at most " +
                         std::to_string(max_remaining()) + " (truncated file?)");
  const std::size_t first = out.size();
  out.resize(first + n);
  unsigned char* dst = out.data() + first;
  while (n > 0) {
    if (pending_pos_ == pending_.size()) {
      // Fast path: whole unpadded quanta without whitespace.
      while (n >= 3 && pos_ + 4 <= text_.size()) {
        const auto* p = reinterpret_cast<const unsigned char*>(text_.data() + pos_);
        const unsigned char a = table[p[0]], b = table[p[1]], c = table[p[2]], d = table[p[3]];
        if ((a | b | c | d) >= 64) break;
        const unsigned v = unsigned(a) << 18 | unsigned(b) << 12 | unsigned(c) << 6 | d;
        dst[0] = static_cast<unsigned char>(v >> 16);
        dst[1] = static_cast<unsigned char>(v >> 8 & 255);
        dst[2] = static_cast<unsigned char>(v & 255);
        dst += 3;
        pos_ += 4;
        n -= 3;
      }
      if (n == 0) return;
      if (!next_quantum(what))
        throw InputError(
            file_, "byte " + std::to_string(file_offset()),
            what + ": base64 data ends " + std::to_string(n) + " bytes early (truncated file?)");
    }
    while (n > 0 && pending_pos_ < pending_.size()) {
      *dst++ = pending_[pending_pos_++];
      --n;
    }
  }
}

}  // namespace hexadapt::io::detail
