// A cursor over a whole legacy-VTK-format file held in memory: the legacy VTK readers and
// reconstruct's model reader scan with it.
//
// Keyword lines are ASCII in both file types; the data after them is either whitespace-
// separated numbers (ASCII files) or big-endian raw values starting right after the
// keyword line's newline (BINARY files). The scanner reads both without iostreams (numbers
// by std::from_chars) and checks every count against the bytes left before anything is
// allocated, so a file that lies about its sizes fails fast with a clear message.
// Errors name the file and the place: "line N" in ASCII files, "byte N" in binary ones.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io {

/// A VTK legacy data type name and how its values are stored.
struct LegacyType {
  std::string_view name;  ///< as written in files (lower case)
  ScalarType type;
  int size;  ///< bytes per value in binary files
  bool is_float;
};

/// The largest count or id a legacy file may give: ids are 32-bit (index_t).
inline constexpr std::int64_t max_legacy_id = std::numeric_limits<index_t>::max();

class LegacyScanner {
 public:
  LegacyScanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  const std::string& file() const { return file_; }
  bool binary() const { return binary_; }
  void set_binary(bool b) { binary_ = b; }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return text_.size() - std::min(pos_, text_.size()); }
  /// Skips whitespace and returns the position of the next token (never before binary data).
  std::size_t mark() {
    skip_space();
    return pos_;
  }

  /// The next line as is (without its newline, trailing '\r' removed); for the header.
  std::string_view line();
  /// The next whitespace-separated token; empty at the end of the file.
  std::string_view token();
  /// The next token without consuming it.
  std::string_view peek_token();
  /// True when only whitespace remains.
  bool at_end();
  /// The next token, which must be present; `what` describes it for the error.
  std::string_view expect_token(const char* what);
  /// The next token as an integer in [lo, hi].
  std::int64_t integer(const char* what, std::int64_t lo = 0, std::int64_t hi = INT64_MAX);
  /// The next token as a floating-point number.
  double real(const char* what);
  /// Skips the rest of the current line with its newline (binary data starts after it).
  void end_line();
  /// Skips lines up to and including the next blank one (METADATA blocks end that way).
  void skip_block();

  /// The type named by the next token; throws for unknown names and for `bit`.
  const LegacyType& data_type();
  /// Reads n values of type t (ASCII numbers or big-endian binary) as doubles.
  std::vector<double> reals(const LegacyType& t, std::size_t n, const char* what);
  /// Reads n integer values of an integer type t.
  std::vector<std::int64_t> integers(const LegacyType& t, std::size_t n, const char* what);
  /// Skips n strings of a `string` array (percent-encoded lines or length-prefixed binary);
  /// returns the first one decoded (empty when n == 0).
  std::string strings(std::size_t n);

  /// "line N" or "byte N" for the current position (or `pos`).
  std::string where(std::size_t pos) const;
  std::string where() const { return where(pos_); }
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_at(std::size_t pos, const std::string& message) const;

 private:
  void skip_space();
  void check_room(std::size_t n, std::size_t bytes_each, const char* what) const;
  template <class T, class Out>
  void binary_values(std::size_t n, Out* out, const char* what);
  template <class Out>
  void dispatch_binary(const LegacyType& t, std::size_t n, Out* out, const char* what);

  std::string_view text_;
  std::string file_;
  std::size_t pos_ = 0;
  bool binary_ = false;
};

/// Decodes VTK's %XX escapes in array names.
std::string decode_name(std::string_view s);
/// Case-insensitive equality with an upper-case keyword.
bool keyword_is(std::string_view token, std::string_view keyword);

}  // namespace hexadapt::io
