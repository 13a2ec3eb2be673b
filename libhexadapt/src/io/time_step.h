// Private to the readers of time series: which step ReadOptions::step or ::time picks.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io::detail {

/// The 0-based step to read among `times` (one per step, in file order): options.step,
/// the step whose time equals options.time (to 1e-9 relative), or the last step. Throws
/// InputError naming `file` and listing the available times when the request matches none,
/// OptionError when both are given.
std::size_t select_time_step(const std::vector<double>& times, const ReadOptions& options,
                             const std::string& file);

/// "0: 0, 1: 0.5, 2: 1" (steps and times), cut after `max_listed` entries.
std::string list_times(const std::vector<double>& times, std::size_t max_listed = 20);

}  // namespace hexadapt::io::detail
