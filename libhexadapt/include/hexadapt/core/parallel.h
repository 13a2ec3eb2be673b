// Thread count and the parallel loops of the library (OpenMP underneath).
//
// Every parallel loop writes to per-item slots or reduces in a fixed order, so results do
// not depend on the thread count: the same input and options give the same bytes.
#pragma once

#include <cstdint>

namespace hexadapt {

/// Sets the number of threads used by the library (0 = all hardware threads).
void set_threads(int n);
/// The number of threads parallel loops will use.
int n_threads();

/// Calls f(i) for i in [0, n) on the library's threads, static schedule. f must only write
/// state owned by item i.
template <class F>
void parallel_for(std::int64_t n, F&& f) {
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) f(i);
}

}  // namespace hexadapt
