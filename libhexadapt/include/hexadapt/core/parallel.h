// Thread count and the parallel loops of the library.
//
// Every parallel loop writes to per-item slots or reduces in a fixed order, so results do
// not depend on the thread count: the same input and options give the same bytes. The loops
// run on the library's own threads, which sleep while they wait (a condition variable, no
// spinning): on a machine whose cores are busy with other work, more threads never cost more
// CPU time than the work itself.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>

namespace hexadapt {

/// Sets the number of threads used by the library (0 = all hardware threads). Before any call,
/// the library uses OMP_NUM_THREADS when it is set to a positive count, else all hardware
/// threads.
void set_threads(int n);
/// The number of threads parallel loops will use.
int n_threads();

namespace detail {
/// Calls body(k) for k in [0, threads) at once, k = 0 on the calling thread and the others on
/// the library's threads, and returns once every call has returned; the first exception thrown
/// (by the lowest k) is rethrown. From inside such a call, or while another thread runs one,
/// the calls are made one after another on the calling thread.
void run_on_threads(int threads, const std::function<void(int)>& body);
}  // namespace detail

/// Calls f(i) for i in [0, n) on the library's threads. The items go in consecutive chunks,
/// each thread taking the next chunk when done with one, so a thread slowed down (a core
/// shared with another process) takes fewer. f must only write state owned by item i: which
/// thread runs an item never changes the result.
template <class F>
void parallel_for(std::int64_t n, F&& f) {
  const auto threads = static_cast<int>(std::min<std::int64_t>(n_threads(), n));
  if (threads <= 1) {
    for (std::int64_t i = 0; i < n; ++i) f(i);
    return;
  }
  const std::int64_t chunks = std::min<std::int64_t>(n, std::int64_t{8} * threads);
  std::atomic<std::int64_t> next{0};
  detail::run_on_threads(threads, [&](int) {
    for (std::int64_t k = next++; k < chunks; k = next++) {
      const std::int64_t end = n * (k + 1) / chunks;
      for (std::int64_t i = n * k / chunks; i < end; ++i) f(i);
    }
  });
}

}  // namespace hexadapt
