#include "exodus_info.h"

#include <optional>

namespace hexadapt::io::detail {

namespace {

std::string escaped(const std::string& s, bool key) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '\\' || (key && (c == ':' || (c == '+' && i == 0)))) out += '\\';
    out += c;
  }
  return out;
}

std::string unescaped(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\' || i + 1 == s.size()) {
      out += s[i];
      continue;
    }
    const char next = s[++i];
    out += next == 'n' ? '\n' : next == 's' ? ' ' : next;
  }
  return out;
}

// Where the key of an entry's text ends: its first ':' without a backslash, followed by ' '.
std::optional<std::size_t> key_end(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\') {
      ++i;
      continue;
    }
    if (text[i] == ':') {
      if (text.compare(i + 1, 1, " ") == 0 || text.compare(i + 1, 2, "\\s") == 0) return i;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

// The Exodus library trims the spaces that end a line, so a line never ends with one: the
// space goes to the start of the next line, or, ending the entry, is written \s.
std::vector<std::string> info_lines(const Metadata& metadata, std::size_t width) {
  std::vector<std::string> lines{info_marker};
  for (const auto& [key, value] : metadata) {
    const std::string text = escaped(key, true) + ": " + escaped(value, false);
    std::string line;
    for (std::size_t i = 0; i < text.size();) {
      const std::size_t unit = text[i] == '\\' ? 2 : 1;
      if (line.size() + unit > width) {
        std::string carry;
        while (!line.empty() && line.back() == ' ') {
          carry += ' ';
          line.pop_back();
        }
        lines.push_back(line);
        line = "+" + carry;
      }
      line += text.substr(i, unit);
      i += unit;
    }
    if (line.back() == ' ') {
      line.pop_back();
      if (line.size() + 2 > width) {
        lines.push_back(line);
        line = "+";
      }
      line += "\\s";
    }
    lines.push_back(line);
  }
  return lines;
}

Metadata metadata_of_info(const std::vector<std::string>& lines) {
  if (lines.empty() || lines.front() != info_marker) return {};
  std::vector<std::string> entries;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (!lines[i].empty() && lines[i][0] == '+' && !entries.empty())
      entries.back() += lines[i].substr(1);
    else
      entries.push_back(lines[i]);
  }
  Metadata out;
  for (const std::string& text : entries)  // a line of no entry (edited by hand) is left out
    if (const std::optional<std::size_t> end = key_end(text))
      // the value after ": ", or after ":\s" (an empty value)
      out.emplace_back(unescaped(text.substr(0, *end)),
                       unescaped(text.substr(*end + (text[*end + 1] == ' ' ? 2 : 3))));
  return out;
}

}  // namespace hexadapt::io::detail
