// Parallel loops that report their progress (core/log.h Progress) while they run.
//
// The long loops of the library (the imprint, the quality of every cell) run over items in
// consecutive blocks and tell the caller how far they are between blocks, from the calling
// thread, as the Progress contract asks.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "hexadapt/core/log.h"
#include "hexadapt/core/parallel.h"

namespace hexadapt {

/// parallel_for in consecutive blocks of items, calling progress(phase, fraction) from the
/// calling thread after each block, the fraction growing from `from` to exactly `to`. Each
/// item still writes only its own state, so the results are those of parallel_for. Without
/// a callback the loop runs as one block.
template <class F>
void parallel_for_progress(std::int64_t n, const Progress& progress, std::string_view phase, F&& f,
                           double from = 0.0, double to = 1.0) {
  if (!progress) {
    parallel_for(n, f);
    return;
  }
  // About a hundred updates: smooth on a terminal, negligible synchronisation.
  const std::int64_t block = std::max<std::int64_t>(256, n / 100);
  for (std::int64_t begin = 0; begin < n; begin += block) {
    const std::int64_t end = std::min(n, begin + block);
    parallel_for(end - begin, [&](std::int64_t i) { f(begin + i); });
    if (end < n)
      progress(phase, from + (to - from) * static_cast<double>(end) / static_cast<double>(n));
  }
  progress(phase, to);
}

}  // namespace hexadapt
