#include "hexadapt/dist/routing.h"

#include <algorithm>

#include "hexadapt/core/error.h"

namespace hexadapt::dist {

Ranges Ranges::of(const Communicator& comm, std::int64_t count) {
  Ranges r;
  r.first.push_back(0);
  for (const std::int64_t c : all_gather_values(comm, std::vector<std::int64_t>{count}))
    r.first.push_back(r.first.back() + c);
  return r;
}

int Ranges::rank_of(std::int64_t g) const {
  if (g < 0 || g >= total())
    throw InternalError("global id " + std::to_string(g) + " outside [0, " +
                        std::to_string(total()) + ")");
  // The last rank whose first id is <= g (ranks holding nothing share their first id).
  const auto it = std::upper_bound(first.begin(), first.end() - 1, g);
  return static_cast<int>(it - first.begin()) - 1;
}

// Every id meets the ranks listing it on the rank it hashes to.
std::vector<std::vector<int>> other_holders(const Communicator& comm,
                                            const std::vector<std::int64_t>& mine,
                                            const std::vector<std::int64_t>& wanted) {
  const int n = comm.size();
  // (id, 2 rank + 1) for a node of mine, (id, 2 rank) for a node wanted.
  std::vector<std::vector<std::int64_t>> to(static_cast<std::size_t>(n));
  for (const std::int64_t is_mine : {1, 0})
    for (const std::int64_t g : is_mine ? mine : wanted) {
      auto& list = to[static_cast<std::size_t>(rank_of_key(&g, 1, n))];
      list.push_back(g);
      list.push_back(2 * static_cast<std::int64_t>(comm.rank()) + is_mine);
    }
  std::vector<std::pair<std::int64_t, std::int64_t>> holders;
  for (const auto& got : all_to_all(comm, std::move(to)))
    for (std::size_t i = 0; i + 1 < got.size(); i += 2) holders.push_back({got[i], got[i + 1]});
  std::sort(holders.begin(), holders.end());
  std::vector<std::vector<std::int64_t>> replies(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < holders.size();) {
    std::size_t end = i + 1;
    while (end < holders.size() && holders[end].first == holders[i].first) ++end;
    for (std::size_t a = i; a < end; ++a)
      for (std::size_t b = i; b < end; ++b) {
        const std::int64_t user = holders[a].second, wanter = holders[b].second;
        if (user % 2 == 1 && wanter % 2 == 0 && user / 2 != wanter / 2) {
          auto& reply = replies[static_cast<std::size_t>(user / 2)];
          reply.push_back(holders[a].first);
          reply.push_back(wanter / 2);
        }
      }
    i = end;
  }
  std::vector<std::vector<int>> out(mine.size());
  for (const auto& got : all_to_all(comm, std::move(replies)))
    for (std::size_t i = 0; i + 1 < got.size(); i += 2) {
      const auto it = std::lower_bound(mine.begin(), mine.end(), got[i]);
      out[static_cast<std::size_t>(it - mine.begin())].push_back(static_cast<int>(got[i + 1]));
    }
  return out;
}

int rank_of_key(const std::int64_t* key, std::size_t n, int size) {
  // splitmix64's finaliser over the words, chained.
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<std::uint64_t>(key[i]) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  return static_cast<int>(h % static_cast<std::uint64_t>(size));
}

}  // namespace hexadapt::dist
