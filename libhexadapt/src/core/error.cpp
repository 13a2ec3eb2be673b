#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {
std::string join(const std::string& file, const std::string& where, const std::string& message) {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (!where.empty()) out += ": " + where;
  return out + ": " + message;
}
}  // namespace

std::string quote_token(std::string_view token, std::size_t max_chars) {
  static const char* const hex = "0123456789abcdef";
  std::string out = "'";
  for (const char c : token.substr(0, max_chars)) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x20 || b == 0x7f)
      out.append({'\\', 'x', hex[b >> 4], hex[b & 15]});
    else
      out += c;
  }
  if (token.size() > max_chars) out += "...";
  return out + "'";
}

InputError::InputError(std::string file, std::string where, std::string message)
    : Error(join(file, where, message)),
      file_(std::move(file)),
      where_(std::move(where)),
      message_(std::move(message)) {}

}  // namespace hexadapt
