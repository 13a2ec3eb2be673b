#include "hexadapt/reconstruct/greedy.h"

#include <algorithm>
#include <numeric>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt::reconstruct {

namespace {

// Fraction vectors of the free pixels, block after block in pixel order.
class Greedy {
 public:
  Greedy(PixelMesh& px, const Fractions& f) : px_(px), f_(f), nm_(f.n_materials()) {
    for (index_t b = 0; b < px.n_blocks(); ++b)
      if (px.block_free(b)) {
        slot_of_block_.push_back(b);
      }
    free_index_.assign(static_cast<std::size_t>(px.n_blocks()), -1);
    for (std::size_t i = 0; i < slot_of_block_.size(); ++i)
      free_index_[static_cast<std::size_t>(slot_of_block_[i])] = static_cast<index_t>(i);
    vf_.assign(slot_of_block_.size() * static_cast<std::size_t>(px.pixels_per_block() * nm_), 0.0);
    next_ = vf_;
    // Neighbours of the free pixels, looked up once for all the diffusion sweeps.
    const int nf = px.faces_per_pixel();
    const std::int64_t n_free =
        static_cast<std::int64_t>(slot_of_block_.size()) * px.pixels_per_block();
    nbr_.resize(static_cast<std::size_t>(n_free * nf));
    // Codes: >= 0 the free index of a free neighbour, -1 none, <= -2 a fixed pixel of
    // material -code - 2.
    slot_label_.assign(static_cast<std::size_t>(n_free), PixelMesh::unassigned);
    parallel_for(n_free, [&](std::int64_t i) {
      const std::int64_t p = pixel_of_slot(i);
      for (int lf = 0; lf < nf; ++lf) {
        const std::int64_t q = px.neighbour(p, lf);
        std::int64_t code = -1;
        if (q >= 0) {
          const index_t qb = px.pixel_block(q);
          code = px.block_free(qb)
                     ? static_cast<std::int64_t>(free_index_[static_cast<std::size_t>(qb)]) *
                               px.pixels_per_block() +
                           (q - px.first_pixel(qb))
                     : -2 - px.label(q);
        }
        nbr_[static_cast<std::size_t>(i * nf + lf)] = code;
      }
    });
    owed_.assign(slot_of_block_.size() * static_cast<std::size_t>(nm_), 0.0);
    for (std::size_t i = 0; i < slot_of_block_.size(); ++i) {
      const index_t b = slot_of_block_[i];
      double vol = 0;
      for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p) vol += weight(p);
      for (int m = 0; m < nm_; ++m) {
        const double share = f(px.block_cell(b), m);
        owed_[i * static_cast<std::size_t>(nm_) + static_cast<std::size_t>(m)] = share * vol;
        for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p) vf(p)[m] = share;
      }
    }
  }

  index_t n_free_blocks() const { return static_cast<index_t>(slot_of_block_.size()); }
  index_t block_of_slot(index_t slot) const {
    return slot_of_block_[static_cast<std::size_t>(slot)];
  }
  /// The slot of a free block, -1 for a fixed one.
  index_t slot_of_block(index_t b) const { return free_index_[static_cast<std::size_t>(b)]; }

  /// A block's whole state: its pixels' labels and fraction vectors, and what it owes.
  void pack(index_t slot, dist::Buffer& out) const {
    const auto [ppb, nm] = sizes();
    const auto s = static_cast<std::size_t>(slot);
    out.put_values(slot_label_.data() + s * ppb, ppb);
    out.put_values(vf_.data() + s * ppb * nm, ppb * nm);
    out.put_values(owed_.data() + s * nm, nm);
  }
  /// Every pixel of the block is assigned: its state changes no more.
  bool complete(index_t slot) const {
    const auto [ppb, nm] = sizes();
    const auto first =
        slot_label_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(slot) * ppb);
    return std::all_of(first, first + static_cast<std::ptrdiff_t>(ppb),
                       [](int m) { return m >= 0; });
  }
  /// Takes a block's state from pack().
  void unpack(index_t slot, dist::Buffer& in) {
    const auto [ppb, nm] = sizes();
    const auto s = static_cast<std::size_t>(slot);
    in.get_values(slot_label_.data() + s * ppb, ppb);
    in.get_values(vf_.data() + s * ppb * nm, ppb * nm);
    in.get_values(owed_.data() + s * nm, nm);
    const std::int64_t first = px_.first_pixel(block_of_slot(slot));
    for (std::size_t i = 0; i < ppb; ++i)
      px_.set_label(first + static_cast<std::int64_t>(i), slot_label_[s * ppb + i]);
  }

  void diffuse(int sweeps) {
    const std::int64_t n =
        static_cast<std::int64_t>(slot_of_block_.size()) * px_.pixels_per_block();
    for (int s = 0; s < sweeps; ++s) {
      parallel_for(n, [&](std::int64_t i) { smooth_one(i); });
      std::swap(vf_, next_);
    }
  }

  void rescale(index_t slot) {
    const index_t b = slot_of_block_[static_cast<std::size_t>(slot)];
    std::vector<double> carried(static_cast<std::size_t>(nm_), 0.0);
    for (std::int64_t p = px_.first_pixel(b); p < px_.first_pixel(b + 1); ++p)
      if (px_.label(p) < 0)
        for (int m = 0; m < nm_; ++m) carried[static_cast<std::size_t>(m)] += weight(p) * vf(p)[m];
    for (std::int64_t p = px_.first_pixel(b); p < px_.first_pixel(b + 1); ++p) {
      if (px_.label(p) >= 0) continue;
      double* v = vf(p);
      for (int m = 0; m < nm_; ++m) {
        const double o = std::max(0.0, owed(slot, m));
        const double c = carried[static_cast<std::size_t>(m)];
        v[m] = c > 0 ? v[m] * o / c : 0.0;
      }
      normalise(v, slot);
    }
  }

  /// Fixes the confident pixels of one free block; returns how many.
  int fix(index_t slot, double threshold) {
    const index_t b = slot_of_block_[static_cast<std::size_t>(slot)];
    std::vector<std::pair<double, std::int64_t>> cand;
    for (std::int64_t p = px_.first_pixel(b); p < px_.first_pixel(b + 1); ++p)
      if (px_.label(p) < 0) {
        const double* v = vf(p);
        const double best = *std::max_element(v, v + nm_);
        if (best >= threshold) cand.emplace_back(best, p);
      }
    std::sort(cand.begin(), cand.end(), [](const auto& a, const auto& c) {
      return a.first != c.first ? a.first > c.first : a.second < c.second;
    });
    int fixed = 0;
    for (const auto& [conf, p] : cand) {
      const double* v = vf(p);
      const int m = static_cast<int>(std::max_element(v, v + nm_) - v);
      if (owed(slot, m) < 0.5 * weight(p)) continue;
      assign(slot, p, m);
      ++fixed;
    }
    return fixed;
  }

  /// Gives every remaining free pixel of the block to the material owed most.
  std::int64_t finish(index_t slot) {
    const index_t b = slot_of_block_[static_cast<std::size_t>(slot)];
    std::int64_t n = 0;
    for (std::int64_t p = px_.first_pixel(b); p < px_.first_pixel(b + 1); ++p)
      if (px_.label(p) < 0) {
        int best = 0;
        for (int m = 1; m < nm_; ++m)
          if (owed(slot, m) > owed(slot, best)) best = m;
        assign(slot, p, best);
        ++n;
      }
    return n;
  }

 private:
  // A pixel's volume in units of its block's first pixel (when that one has a volume): every
  // comparison of volumes stays inside one block, and in these units the pixels of an affine
  // cell weigh exactly 1, so the choices do not depend on the unit or the place of the grid.
  std::pair<std::size_t, std::size_t> sizes() const {
    return {static_cast<std::size_t>(px_.pixels_per_block()), static_cast<std::size_t>(nm_)};
  }
  double weight(std::int64_t p) const {
    const double unit = px_.volume(px_.first_pixel(px_.pixel_block(p)));
    return unit > 0 ? px_.volume(p) / unit : px_.volume(p);
  }
  double* vf(std::int64_t p) {
    const index_t slot = free_index_[static_cast<std::size_t>(px_.pixel_block(p))];
    const std::int64_t local = p - px_.first_pixel(px_.pixel_block(p));
    return vf_.data() + (static_cast<std::int64_t>(slot) * px_.pixels_per_block() + local) * nm_;
  }
  std::int64_t pixel_of_slot(std::int64_t i) const {
    const auto slot = static_cast<std::size_t>(i / px_.pixels_per_block());
    return px_.first_pixel(slot_of_block_[slot]) + i % px_.pixels_per_block();
  }
  double& owed(index_t slot, int m) {
    return owed_[static_cast<std::size_t>(slot) * static_cast<std::size_t>(nm_) +
                 static_cast<std::size_t>(m)];
  }
  void assign(index_t slot, std::int64_t p, int m) {
    px_.set_label(p, m);
    slot_label_[static_cast<std::size_t>(static_cast<std::int64_t>(slot) * px_.pixels_per_block() +
                                         (p - px_.first_pixel(px_.pixel_block(p))))] = m;
    owed(slot, m) -= weight(p);
    double* v = vf(p);
    for (int k = 0; k < nm_; ++k) v[k] = k == m ? 1.0 : 0.0;
  }
  // Materials absent from the cell stay at 0; an all-zero vector becomes uniform over the
  // materials the cell still owes.
  void normalise(double* v, index_t slot) {
    double s = 0;
    for (int m = 0; m < nm_; ++m) s += v[m];
    if (s > 0) {
      for (int m = 0; m < nm_; ++m) v[m] /= s;
      return;
    }
    int owing = 0;
    for (int m = 0; m < nm_; ++m) owing += owed(slot, m) > 0 ? 1 : 0;
    for (int m = 0; m < nm_; ++m) v[m] = owing && owed(slot, m) > 0 ? 1.0 / owing : 0.0;
  }
  void smooth_one(std::int64_t i) {
    double* out = next_.data() + i * nm_;
    const double* self = vf_.data() + i * nm_;
    std::copy(self, self + nm_, out);
    if (slot_label_[static_cast<std::size_t>(i)] >= 0) return;
    const index_t slot = static_cast<index_t>(i / px_.pixels_per_block());
    const CellId c = px_.block_cell(slot_of_block_[static_cast<std::size_t>(slot)]);
    int n = 1;
    const int nf = px_.faces_per_pixel();
    for (int lf = 0; lf < nf; ++lf) {
      const std::int64_t code = nbr_[static_cast<std::size_t>(i * nf + lf)];
      if (code == -1) continue;
      ++n;
      const int fixed =
          code <= -2 ? static_cast<int>(-2 - code) : slot_label_[static_cast<std::size_t>(code)];
      if (fixed >= 0) {
        out[fixed] += 1.0;
      } else {
        const double* w = vf_.data() + code * nm_;
        for (int m = 0; m < nm_; ++m) out[m] += w[m];
      }
    }
    // Only materials present in the cell may grow here.
    double s = 0;
    for (int m = 0; m < nm_; ++m) {
      out[m] = f_(c, m) > 0 ? out[m] / n : 0.0;
      s += out[m];
    }
    if (s > 0)
      for (int m = 0; m < nm_; ++m) out[m] /= s;
  }

  PixelMesh& px_;
  const Fractions& f_;
  int nm_;
  std::vector<index_t> slot_of_block_;
  std::vector<index_t> free_index_;
  std::vector<double> vf_, next_, owed_;
  std::vector<std::int64_t> nbr_;
  std::vector<int> slot_label_;
};

// The free blocks a rank holds but another owns change as their owner assigns them: after
// every round each rank sends the state of its owned free blocks to the ranks that hold them
// (its neighbours), and takes that of its ghost ones. A block goes once more after its last
// pixel is assigned, then never. On one rank nothing travels.
class GhostRefresh {
 public:
  GhostRefresh(const Greedy& g, const PixelMesh& px, const dist::Distribution& where)
      : px_(px), where_(where) {
    const dist::Block& mine = where.block;
    if (mine.held_cells != px.n_cells())
      throw InternalError("greedy: the block does not hold the cells of the pixels");
    owned_.resize(static_cast<std::size_t>(g.n_free_blocks()));
    std::vector<std::pair<std::int64_t, index_t>> own, ghost;  // (global cell id, slot)
    for (index_t s = 0; s < g.n_free_blocks(); ++s) {
      const CellId c = px.block_cell(g.block_of_slot(s));
      owned_[static_cast<std::size_t>(s)] = mine.owns(c) ? 1 : 0;
      (mine.owns(c) ? own : ghost).push_back({mine.global(c), s});
    }
    if (where.comm.size() == 1) return;
    std::sort(own.begin(), own.end());
    std::sort(ghost.begin(), ghost.end());
    const auto ids = [](const std::vector<std::pair<std::int64_t, index_t>>& v) {
      std::vector<std::int64_t> out;
      for (const auto& p : v) out.push_back(p.first);
      return out;
    };
    // The ranks holding each owned free block as a ghost, and the owner of each free ghost:
    // the peers, the same pairs seen from both sides.
    const std::vector<std::vector<int>> holders =
        dist::other_holders(where.comm, ids(own), ids(ghost));
    const std::vector<std::vector<int>> owners =
        dist::other_holders(where.comm, ids(ghost), ids(own));
    for (const auto* ranks : {&holders, &owners})
      for (const std::vector<int>& r : *ranks) peers_.insert(peers_.end(), r.begin(), r.end());
    std::sort(peers_.begin(), peers_.end());
    peers_.erase(std::unique(peers_.begin(), peers_.end()), peers_.end());
    sent_.resize(peers_.size());
    for (std::size_t i = 0; i < own.size(); ++i)
      for (const int r : holders[i]) {
        const auto at = std::lower_bound(peers_.begin(), peers_.end(), r) - peers_.begin();
        sent_[static_cast<std::size_t>(at)].push_back(own[i].second);
      }
  }

  bool owned(index_t slot) const { return owned_[static_cast<std::size_t>(slot)] != 0; }

  /// Exchanges the blocks' states; returns the sum over the ranks of `fixed`.
  std::int64_t operator()(Greedy& g, std::int64_t fixed) {
    if (where_.comm.size() == 1) return fixed;
    std::vector<dist::Buffer> out(peers_.size());
    for (std::size_t i = 0; i < peers_.size(); ++i) {
      std::vector<index_t>& slots = sent_[i];
      out[i].put(static_cast<std::uint64_t>(slots.size()));
      for (index_t s : slots) {
        out[i].put(where_.block.global(px_.block_cell(g.block_of_slot(s))));
        g.pack(s, out[i]);
      }
      slots.erase(
          std::remove_if(slots.begin(), slots.end(), [&](index_t s) { return g.complete(s); }),
          slots.end());
    }
    for (dist::Buffer& in : dist::exchange(where_.comm, peers_, out)) {
      const auto n = in.get<std::uint64_t>();
      for (std::uint64_t i = 0; i < n; ++i) {
        const CellId c = where_.block.local_cell(in.get<std::int64_t>());
        const index_t b = c.valid() && !where_.block.owns(c) ? px_.cell_block(c) : -1;
        if (b < 0 || g.slot_of_block(b) < 0)
          throw InternalError(
              "greedy: a rank sent a block this rank does not hold as a free ghost");
        g.unpack(g.slot_of_block(b), in);
      }
    }
    return dist::sum_in_rank_order(where_.comm, fixed);
  }

 private:
  const PixelMesh& px_;
  const dist::Distribution& where_;
  std::vector<std::uint8_t> owned_;
  std::vector<int>
      peers_;  ///< the ranks holding free blocks this rank owns, or owning ones it holds
  std::vector<std::vector<index_t>> sent_;  ///< per peer, the slots of the owned blocks it holds
};

}  // namespace

double greedy_bytes_per_free_pixel(int n_materials, int dim) {
  return 16.0 * n_materials + 16.0 * dim;
}

int greedy_ghost_layers(int nsub, const GreedyOptions& options) {
  const int reach = (std::max(0, options.diffusion_sweeps) + nsub - 1) / std::max(1, nsub);
  return std::max(1, reach) + 1;
}

GreedyResult greedy_assign(PixelMesh& pixels, const Fractions& fractions,
                           const GreedyOptions& options, const dist::Distribution& where) {
  if (!(options.threshold_step > 0 && options.threshold_step <= 1))
    throw OptionError("greedy threshold step must be in (0, 1]");
  if (options.rounds_per_threshold < 1 || options.diffusion_sweeps < 0)
    throw OptionError("greedy: rounds per threshold >= 1 and diffusion sweeps >= 0");
  Greedy g(pixels, fractions);
  GhostRefresh refresh(g, pixels, where);
  GreedyResult result;
  const index_t nb = g.n_free_blocks();
  std::vector<std::int64_t> fixed(static_cast<std::size_t>(nb));
  // Pixels fixed (or placed) in the owned blocks, summed over the ranks.
  const auto owned_sum = [&] {
    std::int64_t n = 0;
    for (index_t s = 0; s < nb; ++s)
      if (refresh.owned(s)) n += fixed[static_cast<std::size_t>(s)];
    return n;
  };
  double threshold = 1.0;
  int rounds_here = 0;
  std::int64_t owned_free = 0;
  for (index_t s = 0; s < nb; ++s) owned_free += refresh.owned(s) ? pixels.pixels_per_block() : 0;
  std::int64_t left = dist::sum_in_rank_order(where.comm, owned_free);
  while (threshold > 0 && left > 0) {
    ++result.rounds;
    g.diffuse(options.diffusion_sweeps);
    parallel_for(nb, [&](std::int64_t s) { g.rescale(static_cast<index_t>(s)); });
    parallel_for(nb, [&](std::int64_t s) {
      fixed[static_cast<std::size_t>(s)] = g.fix(static_cast<index_t>(s), threshold);
    });
    const std::int64_t n = refresh(g, owned_sum());
    left -= n;
    if (n == 0 || ++rounds_here >= options.rounds_per_threshold) {
      threshold -= options.threshold_step;
      rounds_here = 0;
    }
  }
  parallel_for(nb, [&](std::int64_t s) {
    fixed[static_cast<std::size_t>(s)] = g.finish(static_cast<index_t>(s));
  });
  result.fallback_pixels = dist::sum_in_rank_order(where.comm, owned_sum());
  return result;
}

GreedyResult greedy_assign(PixelMesh& pixels, const Fractions& fractions,
                           const GreedyOptions& options) {
  return greedy_assign(pixels, fractions, options,
                       {dist::serial(), dist::Block::whole(pixels.n_cells(), 0)});
}

}  // namespace hexadapt::reconstruct
