#include "hexadapt/core/log.h"

#include <cstdio>
#include <mutex>
#include <string>
#include <utility>

namespace hexadapt {

namespace {
struct LogState {
  std::mutex mutex;
  LogSink sink = [](LogLevel lvl, std::string_view message) {
    const char* tag = lvl >= LogLevel::error ? "error" : lvl == LogLevel::warning
                                                               ? "warning"
                                                               : "info";
    std::fprintf(stderr, "hexadapt: %s: %.*s\n", tag, static_cast<int>(message.size()),
                 message.data());
  };
  LogLevel level = LogLevel::warning;
};
LogState& state() {
  static LogState s;
  return s;
}
}  // namespace

void set_log_sink(LogSink sink, LogLevel min_level) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().sink = std::move(sink);
  state().level = min_level;
}

void set_log_level(LogLevel min_level) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().level = min_level;
}

LogLevel log_level() {
  std::lock_guard<std::mutex> lock(state().mutex);
  return state().level;
}

void log(LogLevel level, std::string_view message) {
  std::lock_guard<std::mutex> lock(state().mutex);
  if (level < state().level || !state().sink) return;
  state().sink(level, message);
}

Progress progress_part(const Progress& whole, double from, double to, std::string prefix) {
  if (!whole) return nullptr;
  return [whole, from, to, prefix = std::move(prefix)](std::string_view phase, double fraction) {
    whole(prefix + std::string(phase), from + fraction * (to - from));
  };
}

}  // namespace hexadapt
