#include "hexadapt/core/size_text.h"

#include <cmath>

namespace hexadapt {

std::string size_text(double bytes) {
  if (bytes < 1e6) return std::to_string(std::llround(bytes / 1e3)) + " kB";
  if (bytes < 1e10) return std::to_string(std::llround(bytes / 1e6)) + " MB";
  return std::to_string(std::llround(bytes / 1e8) / 10) + "." +
         std::to_string(std::llround(bytes / 1e8) % 10) + " GB";
}

}  // namespace hexadapt
