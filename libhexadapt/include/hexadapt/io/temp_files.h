// Temporary output files that an interrupted run must not leave behind.
//
// AtomicFile records each temporary file here while it exists. A program that wants them
// gone when it is killed by SIGTERM, SIGINT or SIGHUP calls remove_temp_files_on_signals()
// once; the handler only unlink()s the recorded paths (async-signal-safe), then dies by the
// same signal.
#pragma once

#include <string>

namespace hexadapt::io {

/// Temporary files recorded at the same time, at most.
constexpr int max_temp_files = 64;

/// Records `path`; returns its slot, or -1 when the table is full or the path too long (the
/// file then stays behind if a signal arrives).
int record_temp_file(const std::string& path);

/// Forgets slot `slot` (no-op for -1).
void forget_temp_file(int slot);

/// unlink()s every recorded file. Async-signal-safe.
void remove_temp_files() noexcept;

/// Installs the handlers for SIGTERM, SIGINT and SIGHUP.
void remove_temp_files_on_signals();

}  // namespace hexadapt::io
