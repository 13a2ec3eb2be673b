// dist::dual_graph: faces keyed by their sorted global nodes meet on the rank the key hashes
// to; every pair of cells there is an edge, sent back to the ranks holding the two cells.
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
  std::sort(faces.begin(), faces.end(), [](const KeyedFace& a, const KeyedFace& b) {
    return std::tie(a.key, a.cell) < std::tie(b.key, b.cell);
  });
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
  std::vector<std::vector<KeyedFace>> to(static_cast<std::size_t>(n));
  for (const KeyedFace& f : faces_of_cells(nodes_per_cell, cell_nodes, g.first, per_face))
    to[static_cast<std::size_t>(rank_of_key(f.key.data(), static_cast<std::size_t>(per_face), n))]
        .push_back(f);
  std::vector<KeyedFace> mine;
  for (auto& from : all_to_all(comm, std::move(to)))
    mine.insert(mine.end(), from.begin(), from.end());
  std::vector<std::pair<std::int64_t, std::int64_t>> edges;
  for (const auto& from : all_to_all(comm, pair_cells(std::move(mine), cells, n)))
    for (std::size_t i = 0; i + 1 < from.size(); i += 2) edges.push_back({from[i], from[i + 1]});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  g.offsets.assign(static_cast<std::size_t>(n_cells) + 1, 0);
  for (const auto& [cell, other] : edges) ++g.offsets[static_cast<std::size_t>(cell - g.first) + 1];
  for (std::size_t v = 1; v < g.offsets.size(); ++v) g.offsets[v] += g.offsets[v - 1];
  for (const auto& e : edges) g.neighbours.push_back(e.second);
  return g;
}

}  // namespace hexadapt::dist
