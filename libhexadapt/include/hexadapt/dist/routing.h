// Sending values to the rank that decides for them: an all-to-all of plain values, the
// contiguous ranges of a global numbering spread over the ranks (which rank holds global
// id g), and a rank chosen by hashing a key (the rank that meets every copy of the key).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {

/// Sends to[r] to rank r (every rank, this one included) and returns what each rank sent to
/// this one, indexed by rank. Every rank calls it.
template <class T>
std::vector<std::vector<T>> all_to_all(const Communicator& comm, std::vector<std::vector<T>> to) {
  const int n = comm.size();
  std::vector<std::vector<T>> from(static_cast<std::size_t>(n));
  from[static_cast<std::size_t>(comm.rank())] =
      std::move(to[static_cast<std::size_t>(comm.rank())]);
  if (n == 1) return from;
  std::vector<int> peers;
  std::vector<Buffer> out;
  for (int r = 0; r < n; ++r)
    if (r != comm.rank()) {
      peers.push_back(r);
      out.emplace_back();
      out.back().put_vector(to[static_cast<std::size_t>(r)]);
    }
  std::vector<Buffer> in = exchange(comm, peers, std::move(out));
  for (std::size_t i = 0; i < peers.size(); ++i)
    from[static_cast<std::size_t>(peers[i])] = in[i].get_vector<T>();
  return from;
}

/// What every rank sent (all_to_all's result) one after another, in rank order; the parts are
/// released as they are joined.
template <class T>
std::vector<T> joined(std::vector<std::vector<T>> from) {
  std::vector<T> all = from.empty() ? std::vector<T>() : std::move(from[0]);
  for (std::size_t r = 1; r < from.size(); ++r) {
    all.insert(all.end(), from[r].begin(), from[r].end());
    from[r] = std::vector<T>();
  }
  return all;
}

/// A global numbering held by the ranks in contiguous ranges, in rank order: rank r holds
/// the ids [first[r], first[r + 1]).
struct Ranges {
  std::vector<std::int64_t> first;  ///< size() + 1 entries

  /// Every rank's `count` ids, numbered in rank order. Every rank calls it.
  static Ranges of(const Communicator& comm, std::int64_t count);
  int size() const { return static_cast<int>(first.size()) - 1; }
  std::int64_t total() const { return first.back(); }
  /// The rank holding global id g (0 <= g < total()).
  int rank_of(std::int64_t g) const;
};

/// The rank (of `size`) that decides for a key of n 64-bit words: a fixed hash, the same on
/// every rank and in every run.
int rank_of_key(const std::int64_t* key, std::size_t n, int size);

/// For each id of `mine` (increasing), the other ranks whose `wanted` (increasing) lists it,
/// in increasing rank order: e.g. the ranks holding as ghosts the cells this rank owns, or the
/// ranks using the nodes this rank uses. Every rank calls it.
std::vector<std::vector<int>> other_holders(const Communicator& comm,
                                            const std::vector<std::int64_t>& mine,
                                            const std::vector<std::int64_t>& wanted);

/// For each global id of `wanted`, its row of `rows` (`width` values per id this rank holds
/// in `ranges`) from the rank holding it, in the order of `wanted`. Every rank calls it.
template <class T>
std::vector<T> fetch_rows(const Communicator& comm, const Ranges& ranges,
                          const std::vector<T>& rows, int width,
                          const std::vector<std::int64_t>& wanted) {
  const auto n = static_cast<std::size_t>(comm.size());
  const auto w = static_cast<std::size_t>(width);
  std::vector<std::vector<std::int64_t>> asks(n);
  for (const std::int64_t g : wanted)
    asks[static_cast<std::size_t>(ranges.rank_of(g))].push_back(g);
  const std::vector<std::vector<std::int64_t>> asked = all_to_all(comm, asks);
  const std::int64_t mine = ranges.first[static_cast<std::size_t>(comm.rank())];
  std::vector<std::vector<T>> answers(n);
  for (std::size_t r = 0; r < n; ++r)
    for (const std::int64_t g : asked[r]) {
      const auto at = static_cast<std::size_t>(g - mine) * w;
      answers[r].insert(answers[r].end(), rows.begin() + static_cast<std::ptrdiff_t>(at),
                        rows.begin() + static_cast<std::ptrdiff_t>(at + w));
    }
  const std::vector<std::vector<T>> answered = all_to_all(comm, std::move(answers));
  // The answers come back per rank in the order asked: walk `wanted` again.
  std::vector<std::size_t> next(n, 0);
  std::vector<T> out;
  out.reserve(wanted.size() * w);
  for (const std::int64_t g : wanted) {
    const auto r = static_cast<std::size_t>(ranges.rank_of(g));
    const auto at = next[r]++ * w;
    out.insert(out.end(), answered[r].begin() + static_cast<std::ptrdiff_t>(at),
               answered[r].begin() + static_cast<std::ptrdiff_t>(at + w));
  }
  return out;
}

/// Every rank's list, each in `less` order, merged in that order and cut to its first k
/// items: the same on every rank. `write(Buffer&, const T&)` and `read(Buffer&)` carry one
/// item. Every rank calls it.
template <class T, class Write, class Read, class Less>
std::vector<T> first_of_ranks(const Communicator& comm, std::vector<T> mine, std::size_t k,
                              Write write, Read read, Less less) {
  if (comm.size() > 1) {
    Buffer b;
    b.put(static_cast<std::uint64_t>(mine.size()));
    for (const T& x : mine) write(b, x);
    mine.clear();
    for (Buffer& r : all_gather(comm, b))
      for (auto n = r.get<std::uint64_t>(); n > 0; --n) mine.push_back(read(r));
    std::stable_sort(mine.begin(), mine.end(), less);
  }
  if (mine.size() > k) mine.erase(mine.begin() + static_cast<std::ptrdiff_t>(k), mine.end());
  return mine;
}

}  // namespace hexadapt::dist
