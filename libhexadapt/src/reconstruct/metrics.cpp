#include "hexadapt/reconstruct/metrics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "hexadapt/core/parallel.h"

namespace hexadapt::reconstruct {

std::int64_t edgecut(const PixelMesh& pixels) {
  return edgecut(pixels, {dist::serial(), dist::Block::whole(pixels.n_cells(), 0)});
}

std::int64_t edgecut(const PixelMesh& pixels, const dist::Distribution& where) {
  // A face between two ranks' pixels is counted by the rank owning the pixel first in the
  // global order (its cell's global id, then its place in the cell): local ids may order
  // the two otherwise on each rank.
  const auto global_block = [&](std::int64_t p) {
    return where.block.global(pixels.block_cell(pixels.pixel_block(p)));
  };
  const auto first = [&](std::int64_t p, std::int64_t q) {
    const std::int64_t bp = global_block(p), bq = global_block(q);
    return bp != bq ? bp < bq : p < q;
  };
  std::vector<std::int64_t> per_block(static_cast<std::size_t>(pixels.n_blocks()), 0);
  parallel_for(pixels.n_blocks(), [&](std::int64_t b) {
    if (!where.block.owns(pixels.block_cell(static_cast<index_t>(b)))) return;
    std::int64_t cut = 0;
    for (std::int64_t p = pixels.first_pixel(static_cast<index_t>(b));
         p < pixels.first_pixel(static_cast<index_t>(b + 1)); ++p)
      for (int lf = 0; lf < pixels.faces_per_pixel(); ++lf) {
        const std::int64_t q = pixels.neighbour(p, lf);
        if (q >= 0 && pixels.label(q) != pixels.label(p) && first(p, q)) ++cut;
      }
    per_block[static_cast<std::size_t>(b)] = cut;
  });
  return dist::sum_in_rank_order(
      where.comm, std::accumulate(per_block.begin(), per_block.end(), std::int64_t{0}));
}

std::vector<double> block_discrepancy(const PixelMesh& pixels, const Fractions& fractions) {
  std::vector<double> out(static_cast<std::size_t>(pixels.n_blocks()), 0.0);
  const int nm = fractions.n_materials();
  parallel_for(pixels.n_blocks(), [&](std::int64_t bi) {
    const auto b = static_cast<index_t>(bi);
    std::vector<double> vol(static_cast<std::size_t>(nm), 0.0);
    double total = 0;
    for (std::int64_t p = pixels.first_pixel(b); p < pixels.first_pixel(b + 1); ++p) {
      total += pixels.volume(p);
      const int m = pixels.label(p);
      if (m >= 0) vol[static_cast<std::size_t>(m)] += pixels.volume(p);
    }
    double d = 0;
    for (int m = 0; m < nm; ++m)
      d += std::abs(vol[static_cast<std::size_t>(m)] - fractions(pixels.block_cell(b), m) * total);
    out[static_cast<std::size_t>(b)] = d;
  });
  return out;
}

double discrepancy(const PixelMesh& pixels, const Fractions& fractions) {
  return discrepancy(pixels, fractions, {dist::serial(), dist::Block::whole(pixels.n_cells(), 0)});
}

double discrepancy(const PixelMesh& pixels, const Fractions& fractions,
                   const dist::Distribution& where) {
  const auto d = block_discrepancy(pixels, fractions);
  ExactSum sum;
  for (index_t b = 0; b < pixels.n_blocks(); ++b)
    if (where.block.owns(pixels.block_cell(b))) sum.add(d[static_cast<std::size_t>(b)]);
  return dist::exact_sum(where.comm, sum);
}

std::vector<int> largest_remainder_counts(const PixelMesh& pixels, const Fractions& fractions,
                                          index_t block) {
  const int nm = fractions.n_materials();
  const int total = pixels.pixels_per_block();
  const CellId c = pixels.block_cell(block);
  std::vector<int> count(static_cast<std::size_t>(nm));
  std::vector<std::pair<double, int>> rest;
  int sum = 0;
  for (int m = 0; m < nm; ++m) {
    const double share = fractions(c, m) * total;
    const int k = static_cast<int>(std::floor(share));
    count[static_cast<std::size_t>(m)] = k;
    sum += k;
    rest.emplace_back(share - k, m);
  }
  // Largest remainders first; ties to the lower material index.
  std::sort(rest.begin(), rest.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  for (std::size_t i = 0; sum < total && i < rest.size(); ++i, ++sum)
    ++count[static_cast<std::size_t>(rest[i].second)];
  return count;
}

}  // namespace hexadapt::reconstruct
