// Material names in the title line of the model file (model_io.h): separated by spaces, so
// within a name '%', spaces and control bytes are written %XX (two hex digits). Any name then
// survives the round trip ("Body, Nose" is written Body,%20Nose); names without them read as
// before.
#pragma once

#include <cctype>
#include <string>

namespace hexadapt::reconstruct::detail {

inline std::string title_name(const std::string& name) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '%' || c <= ' ' || c == 0x7f) {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += ch;
    }
  }
  return out;
}

// The inverse of title_name; a '%' not followed by two hex digits is kept as it is.
inline std::string name_from_title(const std::string& word) {
  std::string out;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const bool escape = word[i] == '%' && i + 2 < word.size() &&
                        std::isxdigit(static_cast<unsigned char>(word[i + 1])) &&
                        std::isxdigit(static_cast<unsigned char>(word[i + 2]));
    if (!escape) {
      out += word[i];
      continue;
    }
    out += static_cast<char>(std::stoi(word.substr(i + 1, 2), nullptr, 16));
    i += 2;
  }
  return out;
}

}  // namespace hexadapt::reconstruct::detail
