// dist::merge_pieces: the weld (weld.cpp), the repeated cells (repeated_cells.cpp), then the
// points the kept cells use, numbered in the global order by the ranks holding them.
#include "hexadapt/dist/merge_pieces.h"

#include <algorithm>

#include "hexadapt/dist/routing.h"

namespace hexadapt::dist {

namespace {

// The distinct welded points the kept cells use, increasing.
std::vector<std::int64_t> used_points(const PiecesPart& part,
                                      const std::vector<std::int64_t>& nodes,
                                      const std::vector<char>& kept) {
  const auto npc = static_cast<std::size_t>(part.nodes_per_cell);
  std::vector<std::int64_t> used;
  for (std::size_t c = 0; c < kept.size(); ++c)
    if (kept[c])
      used.insert(used.end(), nodes.begin() + static_cast<std::ptrdiff_t>(c * npc),
                  nodes.begin() + static_cast<std::ptrdiff_t>((c + 1) * npc));
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  return used;
}

// The merged mesh's id of each point in `used` (increasing global input points): the points
// used anywhere, numbered in order by the ranks holding them.
std::vector<std::int64_t> merged_ids(const Communicator& comm, const Ranges& points,
                                     const std::vector<std::int64_t>& used, std::int64_t& total) {
  const int n = comm.size();
  std::vector<std::vector<std::int64_t>> tell(static_cast<std::size_t>(n));
  for (const std::int64_t g : used) tell[static_cast<std::size_t>(points.rank_of(g))].push_back(g);
  const std::int64_t first = points.first[static_cast<std::size_t>(comm.rank())];
  const auto held =
      static_cast<std::size_t>(points.first[static_cast<std::size_t>(comm.rank()) + 1] - first);
  std::vector<std::int64_t> id(held, -1);
  for (const auto& from : all_to_all(comm, std::move(tell)))
    for (const std::int64_t g : from) id[static_cast<std::size_t>(g - first)] = 0;
  const auto count = static_cast<std::int64_t>(std::count(id.begin(), id.end(), 0));
  const Ranges numbered = Ranges::of(comm, count);
  total = numbered.total();
  std::int64_t next = numbered.first[static_cast<std::size_t>(comm.rank())];
  for (std::int64_t& i : id)
    if (i == 0) i = next++;
  return fetch_rows(comm, points, id, 1, used);
}

}  // namespace

MergedPart merge_pieces(const Communicator& comm, const PiecesPart& part) {
  const auto npc = static_cast<std::size_t>(part.nodes_per_cell);
  const std::vector<std::int64_t> rep = weld(comm, part);
  const Ranges points = Ranges::of(comm, static_cast<std::int64_t>(part.points.size()));
  const std::int64_t first = points.first[static_cast<std::size_t>(comm.rank())];
  std::vector<std::int64_t> nodes(part.cells.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = rep[part.cells[i].idx()];
  MergedPart m;
  const std::vector<char> repeated = repeated_cells(comm, part, nodes);
  m.kept.resize(repeated.size());
  for (std::size_t c = 0; c < repeated.size(); ++c) m.kept[c] = !repeated[c];
  m.node_sources = used_points(part, nodes, m.kept);
  m.node_ids = merged_ids(comm, points, m.node_sources, m.n_nodes);
  for (std::size_t c = 0; c < m.kept.size(); ++c)
    if (m.kept[c])
      for (std::size_t v = 0; v < npc; ++v) {
        const auto it =
            std::lower_bound(m.node_sources.begin(), m.node_sources.end(), nodes[c * npc + v]);
        m.cells.push_back(NodeId(static_cast<index_t>(it - m.node_sources.begin())));
      }
  const auto kept = static_cast<std::int64_t>(m.cells.size() / std::max<std::size_t>(npc, 1));
  const Ranges cells = Ranges::of(comm, kept);
  m.cell_offset = cells.first[static_cast<std::size_t>(comm.rank())];
  m.n_cells = cells.total();
  std::int64_t welded = 0;
  for (std::size_t q = 0; q < rep.size(); ++q)
    welded += rep[q] != first + static_cast<std::int64_t>(q);
  m.welded = sum_in_rank_order(comm, welded);
  m.repeated = sum_in_rank_order(
      comm, static_cast<std::int64_t>(std::count(repeated.begin(), repeated.end(), 1)));
  return m;
}

}  // namespace hexadapt::dist
