#include "hexadapt/io/legacy_scanner.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>

#include "hexadapt/core/error.h"

namespace hexadapt::io {

namespace {

// vtkIdType is written as 32-bit ints by VTK's legacy writer; long as 64 bits (LP64).
constexpr std::array<LegacyType, 21> kTypes = {{
    {"unsigned_char", ScalarType::uint8, 1, false},
    {"char", ScalarType::int8, 1, false},
    {"signed_char", ScalarType::int8, 1, false},
    {"unsigned_short", ScalarType::uint16, 2, false},
    {"short", ScalarType::int16, 2, false},
    {"unsigned_int", ScalarType::uint32, 4, false},
    {"int", ScalarType::int32, 4, false},
    {"unsigned_long", ScalarType::uint64, 8, false},
    {"long", ScalarType::int64, 8, false},
    {"vtkidtype", ScalarType::int32, 4, false},
    {"vtktypeint8", ScalarType::int8, 1, false},
    {"vtktypeuint8", ScalarType::uint8, 1, false},
    {"vtktypeint16", ScalarType::int16, 2, false},
    {"vtktypeuint16", ScalarType::uint16, 2, false},
    {"vtktypeint32", ScalarType::int32, 4, false},
    {"vtktypeuint32", ScalarType::uint32, 4, false},
    {"vtktypeint64", ScalarType::int64, 8, false},
    {"vtktypeuint64", ScalarType::uint64, 8, false},
    {"float", ScalarType::float32, 4, true},
    {"double", ScalarType::float64, 8, true},
    {"vtktypefloat64", ScalarType::float64, 8, true},
}};

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

char lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

template <class T>
T load_big_endian(const char* p) {
  std::array<unsigned char, sizeof(T)> b;
  std::memcpy(b.data(), p, sizeof(T));
  std::reverse(b.begin(), b.end());  // the file is big-endian, every supported host little
  T v;
  std::memcpy(&v, b.data(), sizeof(T));
  return v;
}

// std::from_chars takes no leading '+', which some writers put before numbers.
const char* number_start(std::string_view t) {
  return t.size() > 1 && t[0] == '+' && t[1] != '-' ? t.data() + 1 : t.data();
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string decode_name(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] == '%' && k + 2 < s.size()) {
      const int hi = hex_digit(s[k + 1]), lo = hex_digit(s[k + 2]);
      if (hi >= 0 && lo >= 0) {
        out += static_cast<char>(hi * 16 + lo);
        k += 2;
        continue;
      }
    }
    out += s[k];
  }
  return out;
}

bool keyword_is(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (std::size_t k = 0; k < token.size(); ++k)
    if (lower(token[k]) != lower(keyword[k])) return false;
  return true;
}

std::string LegacyScanner::where(std::size_t pos) const {
  if (binary_) return "byte " + std::to_string(pos);
  pos = std::min(pos, text_.size());
  // At the end of a file that ends with a newline, the last line is the place.
  if (pos == text_.size() && pos > 0 && text_[pos - 1] == '\n') --pos;
  const auto end = text_.begin() + static_cast<std::ptrdiff_t>(pos);
  return "line " + std::to_string(1 + std::count(text_.begin(), end, '\n'));
}

void LegacyScanner::fail(const std::string& message) const {
  fail_at(pos_, message);
}

void LegacyScanner::fail_at(std::size_t pos, const std::string& message) const {
  throw InputError(file_, where(pos), message);
}

void LegacyScanner::skip_space() {
  while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
}

std::string_view LegacyScanner::line() {
  const std::size_t start = pos_;
  const std::size_t nl = text_.find('\n', pos_);
  const std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
  pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
  std::string_view l = text_.substr(start, end - start);
  if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  return l;
}

std::string_view LegacyScanner::token() {
  skip_space();
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

std::string_view LegacyScanner::peek_token() {
  const std::size_t saved = pos_;
  const std::string_view t = token();
  pos_ = saved;
  return t;
}

bool LegacyScanner::at_end() {
  skip_space();
  return pos_ >= text_.size();
}

std::string_view LegacyScanner::expect_token(const char* what) {
  const std::string_view t = token();
  if (t.empty()) fail(std::string("unexpected end of file, expected ") + what);
  return t;
}

std::int64_t LegacyScanner::integer(const char* what, std::int64_t lo, std::int64_t hi) {
  const std::string_view t = expect_token(what);
  std::int64_t v = 0;
  const auto r = std::from_chars(number_start(t), t.data() + t.size(), v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size())
    fail(std::string("expected ") + what + " (an integer), found " + quote_token(t));
  if (v < lo || v > hi)
    fail(std::string(what) + " " + std::to_string(v) + " out of range [" + std::to_string(lo) +
         ", " + std::to_string(hi) + "]");
  return v;
}

double LegacyScanner::real(const char* what) {
  const std::string_view t = expect_token(what);
  double v = 0;
  const auto r = std::from_chars(number_start(t), t.data() + t.size(), v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size())
    fail(std::string("expected ") + what + " (a number), found " + quote_token(t));
  return v;
}

void LegacyScanner::end_line() {
  const std::size_t nl = text_.find('\n', pos_);
  pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
}

void LegacyScanner::skip_block() {
  end_line();
  while (pos_ < text_.size()) {
    const std::string_view l = line();
    if (std::all_of(l.begin(), l.end(), is_space)) return;
  }
}

const LegacyType& LegacyScanner::data_type() {
  const std::size_t at = mark();
  const std::string_view t = expect_token("a data type");
  for (const LegacyType& d : kTypes)
    if (keyword_is(t, d.name)) return d;
  if (keyword_is(t, "bit")) fail_at(at, "bit arrays are not supported");
  fail_at(at, "unknown data type " + quote_token(t) +
                  " (expected char, short, int, long, float, double and their unsigned "
                  "forms, vtkIdType or vtktypeint64)");
}

void LegacyScanner::check_room(std::size_t n, std::size_t bytes_each, const char* what) const {
  const std::size_t left = text_.size() - std::min(pos_, text_.size());
  // Binary values take bytes_each bytes; ASCII ones at least a character and a separator.
  const bool fits = binary_ ? n <= left / bytes_each : n <= (left + 1) / 2;
  if (!fits)
    fail(std::string("the file ends before the ") + std::to_string(n) + " " + what +
         " announced (" + std::to_string(left) + " bytes left)");
}

template <class T, class Out>
void LegacyScanner::binary_values(std::size_t n, Out* out, const char* what) {
  check_room(n, sizeof(T), what);
  const char* p = text_.data() + pos_;
  for (std::size_t k = 0; k < n; ++k)
    out[k] = static_cast<Out>(load_big_endian<T>(p + k * sizeof(T)));
  pos_ += n * sizeof(T);
}

template <class Out>
void LegacyScanner::dispatch_binary(const LegacyType& t, std::size_t n, Out* out,
                                    const char* what) {
  switch (t.type) {
    case ScalarType::int8:
      return binary_values<std::int8_t>(n, out, what);
    case ScalarType::uint8:
      return binary_values<std::uint8_t>(n, out, what);
    case ScalarType::int16:
      return binary_values<std::int16_t>(n, out, what);
    case ScalarType::uint16:
      return binary_values<std::uint16_t>(n, out, what);
    case ScalarType::int32:
      return binary_values<std::int32_t>(n, out, what);
    case ScalarType::uint32:
      return binary_values<std::uint32_t>(n, out, what);
    case ScalarType::int64:
      return binary_values<std::int64_t>(n, out, what);
    case ScalarType::uint64:
      return binary_values<std::uint64_t>(n, out, what);
    case ScalarType::float32:
      return binary_values<float>(n, out, what);
    case ScalarType::float64:
      return binary_values<double>(n, out, what);
  }
}

std::vector<double> LegacyScanner::reals(const LegacyType& t, std::size_t n, const char* what) {
  if (binary_) {
    end_line();
    check_room(n, static_cast<std::size_t>(t.size), what);
    std::vector<double> out(n);
    dispatch_binary(t, n, out.data(), what);
    return out;
  }
  check_room(n, 2, what);
  std::vector<double> out(n);
  for (double& v : out) v = real(what);
  return out;
}

std::vector<std::int64_t> LegacyScanner::integers(const LegacyType& t, std::size_t n,
                                                  const char* what) {
  if (t.is_float)
    fail(std::string(what) + " must have an integer type, not " + std::string(t.name));
  if (binary_) {
    end_line();
    check_room(n, static_cast<std::size_t>(t.size), what);
    std::vector<std::int64_t> out(n);
    dispatch_binary(t, n, out.data(), what);
    return out;
  }
  check_room(n, 2, what);
  std::vector<std::int64_t> out(n);
  for (std::int64_t& v : out) v = integer(what, INT64_MIN, INT64_MAX);
  return out;
}

std::string LegacyScanner::strings(std::size_t n) {
  std::string first;
  end_line();
  for (std::size_t k = 0; k < n; ++k) {
    std::string s;
    if (!binary_) {
      if (pos_ >= text_.size()) fail("the file ends inside a string array");
      s = decode_name(line());
    } else {
      check_room(1, 1, "string lengths");
      const auto head = static_cast<unsigned char>(text_[pos_]);
      const int kind = head >> 6;
      const std::size_t width = kind == 3 ? 1 : kind == 2 ? 2 : kind == 1 ? 4 : 8;
      check_room(width, 1, "bytes of a string length");
      std::uint64_t len = 0;
      for (std::size_t b = 0; b < width; ++b)
        len = (len << 8) | static_cast<unsigned char>(text_[pos_ + b]);
      len &= width == 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * width - 2)) - 1;
      pos_ += width;
      check_room(static_cast<std::size_t>(len), 1, "string bytes");
      s = std::string(text_.substr(pos_, static_cast<std::size_t>(len)));
      pos_ += static_cast<std::size_t>(len);
    }
    if (k == 0) first = std::move(s);
  }
  return first;
}

}  // namespace hexadapt::io
