// Logging and progress reporting, routed through caller-supplied sinks.
//
// The library never writes to stdout. Messages go to a process-wide sink that the tools
// set (stderr with their -q/-v level); a library user can install their own. Long phases
// report progress through a Progress callback passed in their Options; nullptr means silent.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace hexadapt {

enum class LogLevel { debug = 0, info = 1, warning = 2, error = 3, off = 4 };

using LogSink = std::function<void(LogLevel, std::string_view)>;

/// Installs the sink and the minimum level that reaches it. The default sink writes
/// warnings and errors to stderr.
void set_log_sink(LogSink sink, LogLevel min_level);
void set_log_level(LogLevel min_level);
LogLevel log_level();

void log(LogLevel level, std::string_view message);
inline void log_debug(std::string_view m) { log(LogLevel::debug, m); }
inline void log_info(std::string_view m) { log(LogLevel::info, m); }
inline void log_warning(std::string_view m) { log(LogLevel::warning, m); }

/// Progress of one long phase: called with the phase name and the fraction done in [0,1].
/// Called from the calling thread only, never from inside a parallel region.
using Progress = std::function<void(std::string_view phase, double fraction)>;

/// The progress of a part of a longer task: the part's fractions in [0, 1] reach `whole` as
/// from + fraction x (to - from), its phase names after `prefix`. Empty when `whole` is.
Progress progress_part(const Progress& whole, double from, double to, std::string prefix = {});

}  // namespace hexadapt
