#include "time_step.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

std::string list_times(const std::vector<double>& times, std::size_t max_listed) {
  std::ostringstream out;
  out.precision(10);
  for (std::size_t s = 0; s < times.size() && s < max_listed; ++s)
    out << (s ? ", " : "") << s << ": " << times[s];
  if (times.size() > max_listed) out << ", ... (" << times.size() << " steps)";
  return out.str();
}

std::size_t select_time_step(const std::vector<double>& times, const ReadOptions& options,
                             const std::string& file) {
  if (options.step && options.time)
    throw OptionError("give a time step or a time value, not both");
  const std::string available =
      times.empty() ? "the file has no time steps" : "available steps and times: " + list_times(times);
  if (options.step) {
    if (*options.step < times.size()) return *options.step;
    throw InputError(file, "time steps",
                     "no step " + std::to_string(*options.step) + " (0-based); " + available);
  }
  if (options.time) {
    const double t = *options.time;
    for (std::size_t s = 0; s < times.size(); ++s)
      if (std::abs(times[s] - t) <= 1e-9 * std::max({1.0, std::abs(t), std::abs(times[s])}))
        return s;
    std::ostringstream asked;
    asked.precision(10);
    asked << t;
    throw InputError(file, "time steps", "no step at time " + asked.str() + "; " + available);
  }
  return times.empty() ? 0 : times.size() - 1;
}

}  // namespace hexadapt::io::detail
