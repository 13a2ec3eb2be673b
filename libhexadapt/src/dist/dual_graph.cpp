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

// The faces of local cell c: n nodes each (2 for a quad's edges, 4 for a hex's faces).
std::vector<KeyedFace> faces_of_cells(int nodes_per_cell, const std::vector<std::int64_t>& nodes,
                                      std::int64_t first, int& per_face) {
  const auto npc = static_cast<std::size_t>(nodes_per_cell);
  std::vector<KeyedFace> faces;
  faces.reserve(nodes.size() / npc * (nodes_per_cell == 8 ? 6 : 4));
  per_face = nodes_per_cell == 8 ? 4 : 2;
  for (std::size_t c = 0; c < nodes.size() / npc; ++c) {
    const std::int64_t* n = nodes.data() + c * npc;
    const auto add = [&](const int* local, int count) {
      KeyedFace f{{}, first + static_cast<std::int64_t>(c)};
      for (int i = 0; i < count; ++i) f.key[static_cast<std::size_t>(i)] = n[local[i]];
      std::sort(f.key.begin(), f.key.begin() + count);
      faces.push_back(f);
    };
    if (nodes_per_cell == 8)
      for (const auto& f : ref_hex::face_nodes) add(f.data(), 4);
    else
      for (const auto& f : ref_quad::face_nodes) add(f.data(), 2);
  }
  return faces;
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
  int per_face = 0;
  std::vector<KeyedFace> faces = faces_of_cells(nodes_per_cell, cell_nodes, g.first, per_face);
  // A face this rank holds twice is paired here; the others (a face of the part's boundary,
  // or of three cells or more) go to the rank their key hashes to, to meet the other ranks'.
  std::sort(faces.begin(), faces.end(),
            [](const KeyedFace& a, const KeyedFace& b) { return a.key < b.key; });
  std::vector<std::vector<KeyedFace>> to(static_cast<std::size_t>(n));
  std::size_t twice = 0;  // faces[0, twice): the groups of two, moved to the front
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t end = i + 1;
    while (end < faces.size() && faces[end].key == faces[i].key) ++end;
    for (std::size_t f = i; f < end; ++f)
      if (end - i == 2)
        faces[twice++] = faces[f];
      else
        to[static_cast<std::size_t>(
               rank_of_key(faces[f].key.data(), static_cast<std::size_t>(per_face), n))]
            .push_back(faces[f]);
    i = end;
  }
  faces.resize(twice);
  std::vector<KeyedFace> mine = joined(all_to_all(comm, std::move(to)));
  // Each cell's neighbours, counted, placed, then sorted and made unique per cell (two cells
  // sharing two faces are neighbours once).
  std::vector<std::vector<std::int64_t>> replies =
      all_to_all(comm, pair_cells(std::move(mine), cells, n));
  replies.push_back(
      std::move(pair_cells(std::move(faces), cells, n)[static_cast<std::size_t>(comm.rank())]));
  std::vector<std::int64_t> count(static_cast<std::size_t>(n_cells) + 1, 0);
  for (const auto& from : replies)
    for (std::size_t i = 0; i + 1 < from.size(); i += 2)
      ++count[static_cast<std::size_t>(from[i] - g.first) + 1];
  for (std::size_t v = 1; v < count.size(); ++v) count[v] += count[v - 1];
  std::vector<std::int64_t> all(static_cast<std::size_t>(count.back()));
  std::vector<std::int64_t> next(count.begin(), count.end() - 1);
  for (const auto& from : replies)
    for (std::size_t i = 0; i + 1 < from.size(); i += 2)
      all[static_cast<std::size_t>(next[static_cast<std::size_t>(from[i] - g.first)]++)] =
          from[i + 1];
  g.offsets.assign(1, 0);
  g.neighbours.reserve(all.size());
  for (std::size_t v = 0; v + 1 < count.size(); ++v) {
    const auto first = all.begin() + count[v], end = all.begin() + count[v + 1];
    std::sort(first, end);
    g.neighbours.insert(g.neighbours.end(), first, std::unique(first, end));
    g.offsets.push_back(static_cast<std::int64_t>(g.neighbours.size()));
  }
  return g;
}

}  // namespace hexadapt::dist
