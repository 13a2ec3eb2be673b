#include <charconv>
#include <limits>

#include "hexadapt/core/error.h"
#include "vtk_xml_array.h"
#include "vtk_xml_scalar.h"

namespace hexadapt::io::detail {

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\n' || c == '\t' || c == '\r';
}

struct Tokens {
  std::string_view text;
  std::size_t pos = 0;
  std::string_view next() {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < text.size() && !is_space(text[pos])) ++pos;
    return text.substr(start, pos - start);
  }
};

[[noreturn]] void bad_value(std::string_view token, std::size_t offset, ScalarType t, std::size_t k,
                            const std::string& file, const std::string& what) {
  throw InputError(file, "byte " + std::to_string(offset),
                   what + ": value " + std::to_string(k) + " " + quote_token(token) +
                       " is not a valid " + vtk_name(t));
}

template <class T>
bool parse_one(std::string_view tok, ScalarType t, T& out) {
  const char* b = tok.data();
  const char* e = b + tok.size();
  if (t == ScalarType::float32 || t == ScalarType::float64) {
    double v = 0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec == std::errc::result_out_of_range && r.ptr == e)
      v = 0;  // denormal underflow
    else if (r.ec != std::errc() || r.ptr != e)
      return false;
    // A Float32 array holds floats: round as a binary file would have stored the value.
    if (t == ScalarType::float32) v = static_cast<double>(static_cast<float>(v));
    if constexpr (std::is_same_v<T, double>) {
      out = v;
      return true;
    } else {
      if (!(v == static_cast<double>(static_cast<std::int64_t>(v)))) return false;
      out = static_cast<std::int64_t>(v);
      return true;
    }
  }
  if (t == ScalarType::uint64) {
    std::uint64_t v = 0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e) return false;
    if constexpr (std::is_same_v<T, std::int64_t>)
      if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return false;
    out = static_cast<T>(v);
    return true;
  }
  std::int64_t v = 0;
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e) return false;
  out = static_cast<T>(v);
  return true;
}

template <class T>
void parse(std::string_view text, std::size_t text_offset, ScalarType t, std::size_t n, T* out,
           const std::string& file, const std::string& what) {
  Tokens tokens{text};
  for (std::size_t k = 0; k < n; ++k) {
    const std::string_view tok = tokens.next();
    if (tok.empty())
      throw InputError(
          file, "byte " + std::to_string(text_offset + tokens.pos),
          what + ": found " + std::to_string(k) + " values, expected " + std::to_string(n));
    if (!parse_one(tok, t, out[k]))
      bad_value(tok, text_offset + tokens.pos - tok.size(), t, k, file, what);
  }
  if (!tokens.next().empty())
    throw InputError(file, "byte " + std::to_string(text_offset + tokens.pos),
                     what + ": more than the expected " + std::to_string(n) + " values");
}

}  // namespace

void parse_ascii(std::string_view text, std::size_t text_offset, ScalarType t, std::size_t n,
                 double* out, const std::string& file, const std::string& what) {
  parse(text, text_offset, t, n, out, file, what);
}
void parse_ascii(std::string_view text, std::size_t text_offset, ScalarType t, std::size_t n,
                 std::int64_t* out, const std::string& file, const std::string& what) {
  parse(text, text_offset, t, n, out, file, what);
}

std::size_t count_tokens(std::string_view text) {
  Tokens tokens{text};
  std::size_t n = 0;
  while (!tokens.next().empty()) ++n;
  return n;
}

}  // namespace hexadapt::io::detail
