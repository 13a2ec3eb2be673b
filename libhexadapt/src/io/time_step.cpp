#include "time_step.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

namespace {

std::string time_text(double t) {
  std::ostringstream s;
  s.precision(10);
  s << t;
  return s.str();
}

}  // namespace

std::string list_times(const std::vector<double>& times, std::size_t max_listed) {
  std::string s = std::to_string(times.size()) + (times.size() == 1 ? " step" : " steps") + ":";
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (times.size() > 2 * max_listed && k == max_listed) {
      s += " ...";
      k = times.size() - max_listed;
    }
    s += " " + std::to_string(k) + ": t = " + time_text(times[k]) +
         (k + 1 < times.size() ? "," : "");
  }
  return s;
}

std::size_t select_time_step(const std::vector<double>& times, const ReadOptions& options,
                             const std::string& file) {
  if (options.step && options.time)
    throw OptionError(file + ": give a time step or a time, not both");
  if (times.empty()) {
    if (options.step || options.time)
      throw InputError(file, "time steps", "the file has no time steps (no variables to choose)");
    return 0;
  }
  if (options.step) {
    if (*options.step < times.size()) return *options.step;
    throw InputError(file, "time steps",
                     "no time step " + std::to_string(*options.step) +
                         " (steps count from 0); the series holds " + list_times(times));
  }
  if (options.time) {
    const double scale = std::max(
        {std::abs(times.front()), std::abs(times.back()), std::abs(times.back() - times.front())});
    for (std::size_t k = 0; k < times.size(); ++k)
      if (std::abs(times[k] - *options.time) <= 1e-6 * scale) return k;
    throw InputError(file, "time steps",
                     "no time step at t = " + time_text(*options.time) + "; the series holds " +
                         list_times(times));
  }
  if (times.size() > 1)
    throw InputError(
        file, "time steps",
        "a time series: choose a step with {step} N or {time} T; it holds " + list_times(times));
  return 0;
}

}  // namespace hexadapt::io::detail
