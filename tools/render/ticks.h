// The ticks of a colour bar: a few round values (1, 2 or 5 times a power of ten apart) inside
// a range, with labels short enough to read and precise enough to tell apart, for any range
// a cell array can have: negative, tiny, huge, very narrow around a large value, or a
// single value.
#pragma once

#include <string>
#include <vector>

namespace hexadapt::render {

struct Tick {
  double value = 0;
  std::string label;
};

/// Ticks inside [lo, hi] (either order), in increasing order: the values k x step, step =
/// 1, 2 or 5 x 10^e, for the smallest such step that keeps at most `max_ticks` (at least 2)
/// of them; that is at least two ticks when max_ticks >= 6, at least one otherwise. All are
/// labelled with the same number of decimals (or the same exponent form for very large or
/// small steps), never "-0". A single value (lo == hi) gives one tick; a range narrower than
/// 1e-12 of its values (where round steps run out of double precision) gives its two ends;
/// non-finite ends give no ticks.
std::vector<Tick> nice_ticks(double lo, double hi, int max_ticks = 6);

/// `v` with enough significant digits (at least 4) that the values lo and hi of a range are
/// labelled differently when they differ: for the min and max printed beside a bar.
std::string range_label(double v, double lo, double hi);

}  // namespace hexadapt::render
