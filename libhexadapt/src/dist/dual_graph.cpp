// dist::dual_graph: faces keyed by their sorted global nodes; a face a rank holds twice is an
// edge there, the others meet on the rank the key hashes to, where every pair of cells is an
// edge, sent back to the ranks holding the two cells.
#include "hexadapt/dist/dual_graph.h"

#include <algorithm>
#include <array>

#include "hexadapt/core/error.h"
#include "hexadapt/core/geometry.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt::dist {

namespace {

struct KeyedFace {
  std::array<std::int64_t, 4> key;  ///< sorted nodes; unused entries 0
  std::int64_t cell;
};

// A face as this rank holds it: its nodes by their place among the rank's node ids (so that
// the order of keys is that of the global ids) and its cell by its local id; half the bytes
// of a KeyedFace, the most a rank holds at once while building the graph.
struct LocalFace {
  std::array<std::uint32_t, 4> key;  ///< sorted; unused entries 0
  std::uint32_t cell;
};

// The faces of every cell (`nodes`: node places, nodes_per_cell per cell), sorted by key: 2
// nodes each for a quad's edges, 4 for a hex's faces.
std::vector<LocalFace> sorted_faces(int nodes_per_cell, const std::vector<std::uint32_t>& nodes) {
  const auto npc = static_cast<std::size_t>(nodes_per_cell);
  std::vector<LocalFace> faces;
  faces.reserve(nodes.size() / npc * (nodes_per_cell == 8 ? 6 : 4));
  for (std::size_t c = 0; c < nodes.size() / npc; ++c) {
    const std::uint32_t* n = nodes.data() + c * npc;
    const auto add = [&](const int* local, int count) {
      LocalFace f{{}, static_cast<std::uint32_t>(c)};
      for (int i = 0; i < count; ++i) f.key[static_cast<std::size_t>(i)] = n[local[i]];
      std::sort(f.key.begin(), f.key.begin() + count);
      faces.push_back(f);
    };
    if (nodes_per_cell == 8)
      for (const auto& f : ref_hex::face_nodes) add(f.data(), 4);
    else
      for (const auto& f : ref_quad::face_nodes) add(f.data(), 2);
  }
  std::sort(faces.begin(), faces.end(),
            [](const LocalFace& a, const LocalFace& b) { return a.key < b.key; });
  return faces;
}

// Calls f(begin, end) for each group of faces of one key in `faces` (sorted).
template <class F>
void for_each_key(const std::vector<LocalFace>& faces, const F& f) {
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t end = i + 1;
    while (end < faces.size() && faces[end].key == faces[i].key) ++end;
    f(i, end);
    i = end;
  }
}

// On a deciding rank: each pair of distinct cells sharing a face, as (cell, neighbour) for
// both, sent to the rank holding the cell.
std::vector<std::vector<std::int64_t>> pair_cells(std::vector<KeyedFace> faces, const Ranges& cells,
                                                  int n) {
  // By key only: the pairs of a key are all sent, in whatever order.
  std::sort(faces.begin(), faces.end(),
            [](const KeyedFace& a, const KeyedFace& b) { return a.key < b.key; });
  std::vector<std::vector<std::int64_t>> edges(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t end = i + 1;
    while (end < faces.size() && faces[end].key == faces[i].key) ++end;
    for (std::size_t a = i; a < end; ++a)
      for (std::size_t b = i; b < end; ++b)
        if (faces[a].cell != faces[b].cell) {
          auto& to = edges[static_cast<std::size_t>(cells.rank_of(faces[a].cell))];
          to.push_back(faces[a].cell);
          to.push_back(faces[b].cell);
        }
    i = end;
  }
  return edges;
}

}  // namespace

DistGraph dual_graph(const Communicator& comm, int nodes_per_cell,
                     const std::vector<std::int64_t>& cell_nodes) {
  if (nodes_per_cell != 4 && nodes_per_cell != 8)
    throw InternalError("dual graph of cells of " + std::to_string(nodes_per_cell) + " nodes");
  const auto npc = static_cast<std::size_t>(nodes_per_cell);
  const auto n_cells = static_cast<std::int64_t>(cell_nodes.size() / npc);
  const Ranges cells = Ranges::of(comm, n_cells);
  DistGraph g;
  g.first = cells.first[static_cast<std::size_t>(comm.rank())];
  const int n = comm.size();
  const int per_face = nodes_per_cell == 8 ? 4 : 2;
  std::vector<std::int64_t> ids(cell_nodes);  // this rank's nodes, increasing
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ids.shrink_to_fit();
  if (ids.size() >= (std::size_t(1) << 32) || n_cells >= (std::int64_t(1) << 32))
    throw ResourceError("a dual graph of 2^32 cells or nodes on one rank");
  std::vector<LocalFace> faces;
  {
    std::vector<std::uint32_t> places(cell_nodes.size());
    for (std::size_t i = 0; i < places.size(); ++i)
      places[i] = static_cast<std::uint32_t>(
          std::lower_bound(ids.begin(), ids.end(), cell_nodes[i]) - ids.begin());
    faces = sorted_faces(nodes_per_cell, places);
  }
  // A face this rank holds twice is an edge here; the others (a face of the part's boundary,
  // or of three cells or more) go to the rank their key hashes to, to meet the other ranks'.
  std::vector<std::vector<KeyedFace>> to(static_cast<std::size_t>(n));
  for_each_key(faces, [&](std::size_t first, std::size_t end) {
    if (end - first == 2) return;
    for (std::size_t f = first; f < end; ++f) {
      KeyedFace k{{}, g.first + faces[f].cell};
      for (std::size_t i = 0; i < static_cast<std::size_t>(per_face); ++i)
        k.key[i] = ids[faces[f].key[i]];
      to[static_cast<std::size_t>(rank_of_key(k.key.data(), static_cast<std::size_t>(per_face), n))]
          .push_back(k);
    }
  });
  std::vector<std::vector<std::int64_t>> replies =
      all_to_all(comm, pair_cells(joined(all_to_all(comm, std::move(to))), cells, n));
  // Each cell's neighbours, counted, placed, then sorted and made unique per cell (two cells
  // sharing two faces are neighbours once): the pairs of this rank straight from its faces.
  const auto each_pair = [&](const auto& f) {
    for_each_key(faces, [&](std::size_t first, std::size_t end) {
      if (end - first != 2 || faces[first].cell == faces[first + 1].cell) return;
      f(faces[first].cell, g.first + faces[first + 1].cell);
      f(faces[first + 1].cell, g.first + faces[first].cell);
    });
    for (const auto& from : replies)
      for (std::size_t i = 0; i + 1 < from.size(); i += 2)
        f(static_cast<std::size_t>(from[i] - g.first), from[i + 1]);
  };
  std::vector<std::int64_t> count(static_cast<std::size_t>(n_cells) + 1, 0);
  each_pair([&](std::size_t c, std::int64_t) { ++count[c + 1]; });
  for (std::size_t v = 1; v < count.size(); ++v) count[v] += count[v - 1];
  std::vector<std::int64_t> all(static_cast<std::size_t>(count.back()));
  {
    std::vector<std::int64_t> next(count.begin(), count.end() - 1);
    each_pair([&](std::size_t c, std::int64_t neighbour) {
      all[static_cast<std::size_t>(next[c]++)] = neighbour;
    });
  }
  faces = std::vector<LocalFace>();
  replies = {};
  g.offsets.assign(1, 0);
  g.offsets.reserve(count.size());
  auto kept = all.begin();
  for (std::size_t v = 0; v + 1 < count.size(); ++v) {
    const auto first = all.begin() + count[v], end = all.begin() + count[v + 1];
    std::sort(first, end);
    const auto unique_end = std::unique(first, end);
    for (auto it = first; it != unique_end; ++it) *kept++ = *it;  // kept <= first
    g.offsets.push_back(static_cast<std::int64_t>(kept - all.begin()));
  }
  all.erase(kept, all.end());
  g.neighbours = std::move(all);
  return g;
}

}  // namespace hexadapt::dist
