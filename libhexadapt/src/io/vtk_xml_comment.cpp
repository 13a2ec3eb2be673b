#include "vtk_xml_comment.h"

namespace hexadapt::io::detail {

namespace {

constexpr char hex_digits[] = "0123456789ABCDEF";

void append_hex(std::string& out, unsigned char c) {
  out += "\\x";
  out += hex_digits[c >> 4];
  out += hex_digits[c & 15];
}

// Length of the valid UTF-8 sequence starting at s[i], or 0 (overlong and surrogate forms
// are not told apart: a parser only needs well-formed byte patterns).
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}

// Escapes one key or value; `key` also escapes ':' so that the first ": " of a line
// separates key and value.
void append_escaped(std::string& out, std::string_view s, bool key) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '-' && (i + 1 == s.size() || (i > 0 && s[i - 1] == '-'))) {
      append_hex(out, u);  // "--" and a final '-' cannot appear in a comment
    } else if ((u < 0x20 && c != '\t') || u == 0x7F || c == '<' || (key && c == ':')) {
      append_hex(out, u);  // '<': text searches for "<AppendedData" must not see ours
    } else if (u >= 0x80) {
      const std::size_t n = utf8_length(s, i);
      if (n == 0) {
        append_hex(out, u);
      } else {
        out.append(s.substr(i, n));
        i += n - 1;
      }
    } else {
      out += c;
    }
  }
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::optional<std::string> unescape(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\') {
      out += s[i];
      continue;
    }
    if (i + 1 >= s.size()) return std::nullopt;
    const char e = s[++i];
    if (e == '\\') {
      out += '\\';
    } else if (e == 'n') {
      out += '\n';
    } else if (e == 'x' && i + 2 < s.size() && hex_value(s[i + 1]) >= 0 &&
               hex_value(s[i + 2]) >= 0) {
      out += static_cast<char>(hex_value(s[i + 1]) * 16 + hex_value(s[i + 2]));
      i += 2;
    } else {
      return std::nullopt;
    }
  }
  return out;
}

}  // namespace

std::string metadata_comment(const Metadata& metadata) {
  std::string out = " ";
  out += metadata_comment_title;
  out += '\n';
  for (const auto& [key, value] : metadata) {
    append_escaped(out, key, true);
    out += ": ";
    append_escaped(out, value, false);
    out += '\n';
  }
  return out;
}

std::optional<Metadata> parse_metadata_comment(std::string_view comment) {
  std::string_view rest = comment;
  const std::size_t first = rest.find('\n');
  if (first == std::string_view::npos) return std::nullopt;
  std::string_view title = rest.substr(0, first);
  while (!title.empty() && (title.front() == ' ' || title.front() == '\t')) title.remove_prefix(1);
  while (!title.empty() && (title.back() == ' ' || title.back() == '\r')) title.remove_suffix(1);
  if (title != metadata_comment_title) return std::nullopt;
  rest.remove_prefix(first + 1);
  Metadata out;
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    const std::size_t colon = line.find(": ");
    if (colon == std::string_view::npos) return std::nullopt;
    auto key = unescape(line.substr(0, colon));
    auto value = unescape(line.substr(colon + 2));
    if (!key || !value) return std::nullopt;
    out.emplace_back(std::move(*key), std::move(*value));
  }
  return out;
}

}  // namespace hexadapt::io::detail
