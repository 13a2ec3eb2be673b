#include "hexadapt/io/temp_files.h"

#include <limits.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace hexadapt::io {

namespace {

// A fixed table: the signal handler may neither allocate nor lock.
struct Slot {
  volatile std::sig_atomic_t used = 0;
  char path[PATH_MAX] = {};
};
std::array<Slot, max_temp_files> g_slots;

void on_signal(int sig) {
  remove_temp_files();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

int record_temp_file(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < max_temp_files; ++i) {
    Slot& s = g_slots[static_cast<std::size_t>(i)];
    if (s.used) continue;
    std::memcpy(s.path, path.c_str(), path.size() + 1);
    std::atomic_signal_fence(std::memory_order_seq_cst);
    s.used = 1;
    return i;
  }
  return -1;
}

void forget_temp_file(int slot) {
  if (slot >= 0 && slot < max_temp_files) g_slots[static_cast<std::size_t>(slot)].used = 0;
}

void remove_temp_files() noexcept {
  for (Slot& s : g_slots)
    if (s.used) ::unlink(s.path);
}

void remove_temp_files_on_signals() {
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
    struct sigaction old {};
    ::sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. SIGHUP under nohup stays ignored
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(sig, &action, nullptr);
  }
}

}  // namespace hexadapt::io
