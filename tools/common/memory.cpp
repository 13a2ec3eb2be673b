#include "memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "hexadapt/core/error.h"

namespace hexadapt::cli {

namespace {

double g_last_estimate = 0;

}  // namespace

double parse_memory_size(const std::string& text) {
  if (text.empty()) return physical_memory();
  const std::string bad = "--max-memory: '" + text + "' is not a size (e.g. 8G, 500M)";
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    throw OptionError(bad);
  }
  const std::string unit = text.substr(used);
  const double scale = unit.empty() || unit == "B" ? 1
                       : unit == "K"               ? 1e3
                       : unit == "M"               ? 1e6
                       : unit == "G"               ? 1e9
                       : unit == "T"               ? 1e12
                                                   : -1;
  if (scale < 0 || !(v > 0) || !std::isfinite(v)) throw OptionError(bad);
  return v * scale;
}

double physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGESIZE);
  double bytes =
      pages > 0 && size > 0 ? static_cast<double>(pages) * static_cast<double>(size) : 0.0;
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const auto as = static_cast<double>(limit.rlim_cur);
    bytes = bytes > 0 ? std::min(bytes, as) : as;
  }
  return bytes;
}

void check_memory(const std::string& what, double bytes, double limit) {
  g_last_estimate = bytes;
  if (limit > 0 && bytes > limit)
    throw ResourceError(what + " needs about " + size_text(bytes) + ", more than --max-memory " +
                        size_text(limit));
}

double last_memory_estimate() {
  return g_last_estimate;
}

}  // namespace hexadapt::cli
