#include "hexadapt/reconstruct/annealing.h"

#include <cmath>
#include <numeric>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/reconstruct/metrics.h"
#include "random.h"

namespace hexadapt::reconstruct {

namespace {

double weight(const PixelMesh& px, std::int64_t p, std::int64_t q) {
  const double d = (px.centre(p) - px.centre(q)).norm();
  return d > 0 ? px.mean_width() / d : 1.0;
}

// Energy of pixel p if it had label l.
double local_energy(const PixelMesh& px, std::int64_t p, int l) {
  double e = 0;
  for (int lf = 0; lf < px.faces_per_pixel(); ++lf) {
    const std::int64_t q = px.neighbour(p, lf);
    if (q >= 0 && px.label(q) != l) e += weight(px, p, q);
  }
  return e;
}

void check(const AnnealingOptions& o) {
  if (o.iterations < 0 || o.time_budget < 0)
    throw OptionError("annealing: iterations and time budget must be >= 0");
  if (!(o.t_start > 0 && o.t_end > 0 && o.t_end <= o.t_start))
    throw OptionError("annealing: temperatures must satisfy 0 < t_end <= t_start");
  if (o.swap_tries < 1) throw OptionError("annealing: swap tries must be >= 1");
}

}  // namespace

void largest_remainder_fill(PixelMesh& px, const Fractions& f, std::uint64_t seed) {
  parallel_for(px.n_blocks(), [&](std::int64_t bi) {
    const auto b = static_cast<index_t>(bi);
    if (!px.block_free(b)) return;
    const auto count = largest_remainder_counts(px, f, b);
    std::vector<int> labels;
    for (std::size_t m = 0; m < count.size(); ++m) labels.insert(labels.end(), static_cast<std::size_t>(count[m]), static_cast<int>(m));
    // One stream per cell, so the fill does not depend on the thread count.
    detail::Random rng(seed ^ (0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(px.block_cell(b).value() + 1)));
    for (std::size_t i = labels.size(); i > 1; --i)
      std::swap(labels[i - 1], labels[static_cast<std::size_t>(rng.below(static_cast<std::int64_t>(i)))]);
    for (std::size_t i = 0; i < labels.size(); ++i)
      px.set_label(px.first_pixel(b) + static_cast<std::int64_t>(i), labels[i]);
  });
}

double pair_energy(const PixelMesh& px) {
  std::vector<double> per_block(static_cast<std::size_t>(px.n_blocks()), 0.0);
  parallel_for(px.n_blocks(), [&](std::int64_t b) {
    double e = 0;
    for (std::int64_t p = px.first_pixel(static_cast<index_t>(b)); p < px.first_pixel(static_cast<index_t>(b + 1)); ++p)
      for (int lf = 0; lf < px.faces_per_pixel(); ++lf) {
        const std::int64_t q = px.neighbour(p, lf);
        if (q > p && px.label(q) != px.label(p)) e += weight(px, p, q);
      }
    per_block[static_cast<std::size_t>(b)] = e;
  });
  return std::accumulate(per_block.begin(), per_block.end(), 0.0);
}

AnnealingResult annealing_assign(PixelMesh& px, const Fractions& f, const AnnealingOptions& o) {
  check(o);
  AnnealingResult r;
  largest_remainder_fill(px, f, o.seed);
  r.initial_edgecut = edgecut(px);
  r.initial_energy = pair_energy(px);
  std::vector<index_t> free_blocks;
  for (index_t b = 0; b < px.n_blocks(); ++b)
    if (px.block_free(b)) free_blocks.push_back(b);
  if (free_blocks.empty()) {
    r.final_energy = r.initial_energy;
    return r;
  }
  const std::int64_t ppb = px.pixels_per_block();
  const std::int64_t total = o.iterations > 0 ? o.iterations
                                              : 200 * ppb * static_cast<std::int64_t>(free_blocks.size());
  r.time_limited = o.time_budget > 0;
  detail::Random rng(o.seed * 0xD1B54A32D192ED03ull + 7);
  const double cooling = std::log(o.t_end / o.t_start);
  const Timer clock;
  double progress = 0;
  for (std::int64_t it = 0;; ++it) {
    if (r.time_limited) {
      if ((it & 1023) == 0) progress = clock.seconds() / o.time_budget;
      if (progress >= 1) break;
    } else {
      if (it >= total) break;
      progress = static_cast<double>(it) / static_cast<double>(total);
    }
    ++r.attempts;
    const index_t b = free_blocks[static_cast<std::size_t>(rng.below(static_cast<std::int64_t>(free_blocks.size())))];
    const std::int64_t p0 = px.first_pixel(b) + rng.below(ppb);
    std::int64_t p1 = -1;
    for (int t = 0; t < o.swap_tries && p1 < 0; ++t) {
      const std::int64_t q = px.first_pixel(b) + rng.below(ppb);
      if (px.label(q) != px.label(p0)) p1 = q;
    }
    if (p1 < 0) continue;
    const int l0 = px.label(p0), l1 = px.label(p1);
    const double before = local_energy(px, p0, l0) + local_energy(px, p1, l1);
    px.set_label(p0, l1);
    px.set_label(p1, l0);
    const double after = local_energy(px, p0, l1) + local_energy(px, p1, l0);
    const double de = after - before;
    const double temperature = o.t_start * std::exp(cooling * progress);
    if (de <= 0 || rng.uniform() < std::exp(-de / temperature)) {
      ++r.accepted;
    } else {
      px.set_label(p0, l0);
      px.set_label(p1, l1);
    }
  }
  r.final_energy = pair_energy(px);
  return r;
}

}  // namespace hexadapt::reconstruct
