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
