// The weld of dist::merge_pieces: space is cut into cubes (buckets) twice the largest
// tolerance, so the points within a point's tolerance lie in the <= 2 x 2 x 2 buckets its
// tolerance box touches. Each bucket has a deciding rank (a hash of the key of its block of
// buckets); every point goes to the ranks deciding the buckets its box touches, its own
// bucket's among them, where it is a candidate too, so the rank deciding a bucket sees every
// pair a search there can find (a point far from every other piece, near_other_pieces, can
// match nothing and is not sent). Each
// searcher's earliest match comes back to the point's rank; chains (q to p to an earlier p')
// are then followed by asking the rank holding the match, until no rank changes a point.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "hexadapt/dist/merge_pieces.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt::dist {

namespace {

using Key = std::array<std::int64_t, 3>;

struct WeldPoint {
  std::int64_t id;
  std::int64_t piece;
  double x, y, z, tolerance;
  std::int64_t home;  ///< 1 on the rank of the point's own bucket: a candidate there
  Vec3 point() const { return {x, y, z}; }
};

// Bucket keys over the whole point set (every rank's bounds and largest tolerance).
struct Buckets {
  Vec3 lo;
  double size = 0;  ///< 0: no point can weld

  Key key(const Vec3& p, double shift) const {
    Key k;
    for (int a = 0; a < 3; ++a)
      k[static_cast<std::size_t>(a)] =
          static_cast<std::int64_t>(std::floor((p[a] + shift - lo[a]) / size));
    return k;
  }
  /// The deciding rank of bucket k: that of its block of buckets_per_block^3 buckets, so that
  /// a tolerance box across two buckets mostly has one deciding rank (each rank it touches
  /// gets a copy of the point).
  int rank(const Key& k, int n) const {
    Key block;
    for (std::size_t a = 0; a < 3; ++a)
      block[a] = k[a] >= 0 ? k[a] / buckets_per_block : -((-k[a] - 1) / buckets_per_block) - 1;
    return rank_of_key(block.data(), 3, n);
  }
  static constexpr std::int64_t buckets_per_block = 64;
};

Buckets buckets_of(const Communicator& comm, const PiecesPart& part) {
  std::vector<double> mine(7, std::numeric_limits<double>::infinity());
  for (int a = 3; a < 7; ++a) mine[static_cast<std::size_t>(a)] = -mine[0];
  mine[6] = 0;
  for (std::size_t q = 0; q < part.points.size(); ++q) {
    for (int a = 0; a < 3; ++a) {
      mine[static_cast<std::size_t>(a)] =
          std::min(mine[static_cast<std::size_t>(a)], part.points[q][a]);
      mine[static_cast<std::size_t>(a + 3)] =
          std::max(mine[static_cast<std::size_t>(a + 3)], part.points[q][a]);
    }
    mine[6] = std::max(mine[6], part.tolerance[q]);
  }
  const std::vector<double> all = all_gather_values(comm, mine);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double max_tol = 0;
  for (std::size_t r = 0; r + 6 < all.size(); r += 7) {
    lo = lo.cwiseMin(Vec3(all[r], all[r + 1], all[r + 2]));
    hi = hi.cwiseMax(Vec3(all[r + 3], all[r + 4], all[r + 5]));
    max_tol = std::max(max_tol, all[r + 6]);
  }
  Buckets b;
  b.lo = lo;
  // Keys stay well inside 64 bits (a tolerance below the extent / 2^52 is not resolvable).
  if (max_tol > 0) b.size = std::max(2 * max_tol, (hi - lo).maxCoeff() / 4503599627370496.0);
  return b;
}

// The ranks of the buckets q's tolerance box touches (at most 2 per axis), each once; the
// count is returned.
int search_ranks(const Buckets& b, const WeldPoint& q, int n, std::array<int, 8>& ranks) {
  const Key from = b.key(q.point(), -q.tolerance), to = b.key(q.point(), q.tolerance);
  int count = 0;
  for (std::int64_t i = from[0]; i <= to[0]; ++i)
    for (std::int64_t j = from[1]; j <= to[1]; ++j)
      for (std::int64_t k = from[2]; k <= to[2]; ++k) {
        const int r = n == 1 ? 0 : b.rank({i, j, k}, n);
        if (std::find(ranks.begin(), ranks.begin() + count, r) == ranks.begin() + count)
          ranks[static_cast<std::size_t>(count++)] = r;
      }
  return count;
}

// On a deciding rank: the earliest candidate of another piece within both tolerances of each
// point received, looked up in the buckets of its box that this rank decides for.
std::vector<std::vector<std::int64_t>> earliest_matches(const Buckets& b,
                                                        std::vector<std::vector<WeldPoint>> from,
                                                        const Ranges& ranges, int rank, int n) {
  const std::vector<WeldPoint> all = joined(std::move(from));
  // The candidates by bucket, then id: `all` comes in increasing ids (every rank's in rank
  // order, each in its order).
  std::vector<std::pair<Key, std::size_t>> sorted;
  sorted.reserve(all.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].home) sorted.push_back({b.key(all[i].point(), 0), i});
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<std::int64_t>> replies(static_cast<std::size_t>(n));
  const auto search = [&](const WeldPoint& q) {
    const Key lo = b.key(q.point(), -q.tolerance), hi = b.key(q.point(), q.tolerance);
    std::int64_t best = q.id;
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
          const Key key{i, j, k};
          if (n > 1 && b.rank(key, n) != rank) continue;
          auto it =
              std::lower_bound(sorted.begin(), sorted.end(), std::pair<Key, std::size_t>{key, 0});
          for (; it != sorted.end() && it->first == key; ++it) {
            const WeldPoint& p = all[it->second];
            if (p.id < best && p.piece != q.piece &&
                (p.point() - q.point()).norm() <= std::min(p.tolerance, q.tolerance))
              best = p.id;
          }
        }
    if (best != q.id) {
      auto& to = replies[static_cast<std::size_t>(ranges.rank_of(q.id))];
      to.push_back(q.id);
      to.push_back(best);
    }
  };
  // The candidates first, in bucket order (neighbours looked up one after another), then the
  // points searching from another rank's bucket.
  for (const auto& [key, i] : sorted) search(all[i]);
  for (const WeldPoint& q : all)
    if (!q.home) search(q);
  return replies;
}

// rep[q] <- rep[rep[q]] on every rank at once, until no rank changes one.
void follow_chains(const Communicator& comm, const Ranges& ranges, std::vector<std::int64_t>& rep) {
  for (;;) {
    const std::vector<std::int64_t> next = fetch_rows(comm, ranges, rep, 1, rep);
    const std::int64_t changed =
        sum_in_rank_order<std::int64_t>(comm, static_cast<std::int64_t>(next != rep));
    if (changed == 0) return;
    rep = next;
  }
}

}  // namespace

std::vector<std::int64_t> weld(const Communicator& comm, const PiecesPart& part,
                               const std::vector<char>& near) {
  const Ranges ranges = Ranges::of(comm, static_cast<std::int64_t>(part.points.size()));
  const std::int64_t first = ranges.first[static_cast<std::size_t>(comm.rank())];
  std::vector<std::int64_t> rep(part.points.size());
  for (std::size_t q = 0; q < rep.size(); ++q) rep[q] = first + static_cast<std::int64_t>(q);
  const Buckets b = buckets_of(comm, part);
  if (b.size <= 0) return rep;
  const int n = comm.size();
  std::vector<std::vector<WeldPoint>> to(static_cast<std::size_t>(n));
  std::array<int, 8> ranks{};
  for (std::size_t q = 0; q < rep.size(); ++q) {
    if (!near[q] || !(part.tolerance[q] > 0)) continue;  // stays home: nothing to weld with
    const Vec3& p = part.points[q];
    WeldPoint w{rep[q], part.point_piece[q], p[0], p[1], p[2], part.tolerance[q], 0};
    const int home = n == 1 ? 0 : b.rank(b.key(p, 0), n);
    for (int i = 0, count = search_ranks(b, w, n, ranks); i < count; ++i) {
      const int r = ranks[static_cast<std::size_t>(i)];
      w.home = r == home;
      to[static_cast<std::size_t>(r)].push_back(w);
    }
  }
  const auto replies = all_to_all(
      comm, earliest_matches(b, all_to_all(comm, std::move(to)), ranges, comm.rank(), n));
  for (const auto& from : replies)
    for (std::size_t i = 0; i + 1 < from.size(); i += 2) {
      std::int64_t& r = rep[static_cast<std::size_t>(from[i] - first)];
      r = std::min(r, from[i + 1]);
    }
  follow_chains(comm, ranges, rep);
  return rep;
}

}  // namespace hexadapt::dist
