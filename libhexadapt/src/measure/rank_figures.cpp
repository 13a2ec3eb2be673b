#include "rank_figures.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "hexadapt/core/exact_sum.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt {

namespace {

// A key in the order of the doubles (negative values below positive ones, NaN after +inf).
std::uint64_t order_key(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return (b >> 63) != 0 ? ~b : b | (std::uint64_t{1} << 63);
}

double from_key(std::uint64_t k) {
  const std::uint64_t b = (k >> 63) != 0 ? k & ~(std::uint64_t{1} << 63) : ~k;
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

}  // namespace

QualityStats stats(const dist::Communicator& comm, const std::vector<double>& values) {
  const double inf = std::numeric_limits<double>::infinity();
  double lo = inf, hi = -inf;
  ExactSum sum;
  for (const double x : values) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    sum.add(x);
  }
  const std::int64_t n = total(comm, static_cast<std::int64_t>(values.size()));
  QualityStats s;
  if (n == 0) return s;
  const double mean = dist::exact_sum(comm, sum) / double(n);
  const std::vector<double> ends = dist::all_gather_values(comm, std::vector<double>{lo, hi});
  s.min = inf;
  s.max = -inf;
  for (std::size_t r = 0; r < ends.size(); r += 2) {
    s.min = std::min(s.min, ends[r]);
    s.max = std::max(s.max, ends[r + 1]);
  }
  s.mean = mean;
  return s;
}

std::int64_t total(const dist::Communicator& comm, std::int64_t count) {
  return dist::sum_in_rank_order(comm, count);
}

std::vector<index_t> summed(const dist::Communicator& comm, std::vector<index_t> counts) {
  if (comm.size() == 1) return counts;
  const std::vector<index_t> all = dist::all_gather_values(comm, counts);
  std::fill(counts.begin(), counts.end(), 0);
  for (std::size_t i = 0; i < all.size(); ++i) counts[i % counts.size()] += all[i];
  return counts;
}

double kth_value(const dist::Communicator& comm, const std::vector<double>& values,
                 std::int64_t k) {
  std::vector<std::uint64_t> keys(values.size());
  std::transform(values.begin(), values.end(), keys.begin(), order_key);
  if (total(comm, static_cast<std::int64_t>(keys.size())) <= k)
    return std::numeric_limits<double>::quiet_NaN();
  if (comm.size() == 1) {  // all values here: select directly
    const auto at = keys.begin() + static_cast<std::ptrdiff_t>(k);
    std::nth_element(keys.begin(), at, keys.end());
    return from_key(*at);
  }
  std::sort(keys.begin(), keys.end());
  // The smallest key with more than k keys at or below it, bit by bit from the top.
  std::uint64_t key = 0;
  for (int bit = 63; bit >= 0; --bit) {
    const std::uint64_t below = key | ((std::uint64_t{1} << bit) - 1);  // bit left at 0
    const auto at_or_below =
        static_cast<std::int64_t>(std::upper_bound(keys.begin(), keys.end(), below) - keys.begin());
    if (total(comm, at_or_below) <= k) key |= std::uint64_t{1} << bit;
  }
  return from_key(key);
}

std::pair<double, std::int64_t> extreme_with_id(const dist::Communicator& comm,
                                                std::pair<double, std::int64_t> mine,
                                                bool highest) {
  if (comm.size() == 1) return mine;
  const std::vector<double> values = dist::all_gather_values(comm, std::vector<double>{mine.first});
  const std::vector<std::int64_t> ids =
      dist::all_gather_values(comm, std::vector<std::int64_t>{mine.second});
  std::pair<double, std::int64_t> best{0.0, -1};
  for (std::size_t r = 0; r < ids.size(); ++r) {
    if (ids[r] < 0) continue;
    const bool better = best.second < 0 ||
                        (highest ? values[r] > best.first : values[r] < best.first) ||
                        (values[r] == best.first && ids[r] < best.second);
    if (better) best = {values[r], ids[r]};
  }
  return best.second < 0 ? mine : best;
}

std::vector<CellId> first_of_ranks(const dist::Communicator& comm, std::vector<CellId> mine,
                                   int k) {
  return dist::first_of_ranks(
      comm, std::move(mine), static_cast<std::size_t>(std::max(k, 0)),
      [](dist::Buffer& b, CellId c) { b.put(c); }, [](dist::Buffer& b) { return b.get<CellId>(); },
      std::less<CellId>());
}

}  // namespace hexadapt
