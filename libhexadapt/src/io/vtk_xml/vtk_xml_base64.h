// Private to the VTK XML reader and writer: base64 as VTK uses it for inline and appended
// binary data. VTK encodes the header of an array and its data as separate base64 streams
// (each padded), so the decoder continues after a padded quantum instead of stopping.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace hexadapt::io::detail {

/// Standard base64 (RFC 4648) with padding.
std::string base64_encode(const unsigned char* bytes, std::size_t n);

/// Decodes base64 text in steps. Whitespace is skipped; a padded quantum ends one stream and
/// the next character starts another. Errors name the byte offset in the file.
class Base64Reader {
 public:
  /// `text` starts at byte `file_offset` of `file`; `where` names what is being decoded.
  Base64Reader(std::string_view text, std::size_t file_offset, std::string file);
  /// Appends exactly n decoded bytes to `out`. Throws InputError on a character outside
  /// the alphabet or when the text ends first (`what` names the array).
  void read(std::size_t n, std::vector<unsigned char>& out, const std::string& what);
  /// An upper bound on the bytes still decodable (to check sizes before allocating).
  std::size_t max_remaining() const {
    return pending_.size() - pending_pos_ + (text_.size() - pos_) / 4 * 3 + 3;
  }
  /// File offset of the next undecoded character.
  std::size_t file_offset() const { return file_offset_ + pos_; }

 private:
  bool next_quantum(const std::string& what);

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t file_offset_;
  std::string file_;
  std::vector<unsigned char> pending_;  // decoded bytes of the last quantum not yet handed out
  std::size_t pending_pos_ = 0;
};

}  // namespace hexadapt::io::detail
