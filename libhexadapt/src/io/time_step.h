// Private to the readers of time series: which step ReadOptions::step or ::time picks.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io::detail {

/// The 0-based step to read among `times` (one per step, in file order): options.step, or
/// the step whose time equals options.time (to 1e-6 of the times' scale), or the only step.
/// Throws InputError naming `file` and listing the steps and times when the request matches
/// none or when a series of several steps gets no request; OptionError when both are given.
std::size_t select_time_step(const std::vector<double>& times, const ReadOptions& options,
                             const std::string& file);

/// "3 steps: 0: t = 0, 1: t = 0.5, 2: t = 1"; a long series shows its first and last
/// `max_listed` steps.
std::string list_times(const std::vector<double>& times, std::size_t max_listed = 8);

}  // namespace hexadapt::io::detail
