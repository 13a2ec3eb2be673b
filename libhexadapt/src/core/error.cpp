#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {
std::string join(const std::string& file, const std::string& where, const std::string& message) {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (!where.empty()) out += ": " + where;
  return out + ": " + message;
}
}  // namespace

InputError::InputError(std::string file, std::string where, std::string message)
    : Error(join(file, where, message)),
      file_(std::move(file)),
      where_(std::move(where)),
      message_(std::move(message)) {}

}  // namespace hexadapt
