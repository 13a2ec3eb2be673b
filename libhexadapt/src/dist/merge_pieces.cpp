// dist::merge_pieces: the points near other pieces (near_pieces.cpp), the weld (weld.cpp),
// the repeated cells (repeated_cells.cpp), then the points the kept cells use, numbered in
// the global order by the ranks holding them.
#include "hexadapt/dist/merge_pieces.h"

#include <algorithm>

#include "hexadapt/dist/routing.h"

namespace hexadapt::dist {

namespace {

// The welded points the kept cells use, each once, increasing; `node_of` gets, for each
// local point a kept cell uses, its place among them.
std::vector<std::int64_t> used_points(const PiecesPart& part,
                                      const std::vector<std::int64_t>& welded,
                                      const std::vector<char>& kept,
                                      std::vector<index_t>& node_of) {
  const auto npc = static_cast<std::size_t>(part.nodes_per_cell);
  node_of.assign(part.points.size(), -1);
  for (std::size_t c = 0; c < kept.size(); ++c)
    if (kept[c])
      for (std::size_t v = 0; v < npc; ++v) node_of[part.cells[c * npc + v].idx()] = 0;
  std::vector<std::int64_t> used;
  for (std::size_t q = 0; q < node_of.size(); ++q)
    if (node_of[q] == 0) used.push_back(welded[q]);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (std::size_t q = 0; q < node_of.size(); ++q)
    if (node_of[q] == 0)
      node_of[q] = static_cast<index_t>(std::lower_bound(used.begin(), used.end(), welded[q]) -
                                        used.begin());
  return used;
}

// The merged mesh's id of each point in `used` (increasing global input points): the points
// used anywhere, numbered in order by the ranks holding them.
std::vector<std::int64_t> merged_ids(const Communicator& comm, const Ranges& points,
                                     const std::vector<std::int64_t>& used, std::int64_t& total) {
  const int n = comm.size();
  std::vector<std::vector<std::int64_t>> tell(static_cast<std::size_t>(n));
  for (const std::int64_t g : used) tell[static_cast<std::size_t>(points.rank_of(g))].push_back(g);
  const auto r = static_cast<std::size_t>(comm.rank());
  const std::int64_t first = points.first[r];
  std::vector<std::int64_t> id(static_cast<std::size_t>(points.first[r + 1] - first), -1);
  for (const auto& from : all_to_all(comm, std::move(tell)))
    for (const std::int64_t g : from) id[static_cast<std::size_t>(g - first)] = 0;
  const Ranges numbered =
      Ranges::of(comm, static_cast<std::int64_t>(std::count(id.begin(), id.end(), 0)));
  total = numbered.total();
  std::int64_t next = numbered.first[r];
  for (std::int64_t& i : id)
    if (i == 0) i = next++;
  return fetch_rows(comm, points, id, 1, used);
}

}  // namespace

MergedPart merge_pieces(const Communicator& comm, const PiecesPart& part) {
  const auto npc = static_cast<std::size_t>(part.nodes_per_cell);
  const std::vector<char> near = near_other_pieces(comm, part);
  const std::vector<std::int64_t> welded = weld(comm, part, near);
  const Ranges points = Ranges::of(comm, static_cast<std::int64_t>(part.points.size()));
  const std::int64_t first = points.first[static_cast<std::size_t>(comm.rank())];
  MergedPart m;
  const std::vector<char> repeated = repeated_cells(comm, part, welded, near);
  m.kept.resize(repeated.size());
  for (std::size_t c = 0; c < repeated.size(); ++c) m.kept[c] = !repeated[c];
  std::vector<index_t> node_of;
  m.node_sources = used_points(part, welded, m.kept, node_of);
  m.node_ids = merged_ids(comm, points, m.node_sources, m.n_nodes);
  m.cells.reserve(part.cells.size());
  for (std::size_t c = 0; c < m.kept.size(); ++c)
    if (m.kept[c])
      for (std::size_t v = 0; v < npc; ++v)
        m.cells.push_back(NodeId(node_of[part.cells[c * npc + v].idx()]));
  const Ranges cells = Ranges::of(comm, static_cast<std::int64_t>(m.cells.size() / npc));
  m.cell_offset = cells.first[static_cast<std::size_t>(comm.rank())];
  m.n_cells = cells.total();
  std::int64_t welded_here = 0;
  for (std::size_t q = 0; q < welded.size(); ++q)
    welded_here += welded[q] != first + static_cast<std::int64_t>(q);
  m.welded = sum_in_rank_order(comm, welded_here);
  m.repeated = sum_in_rank_order(
      comm, static_cast<std::int64_t>(std::count(repeated.begin(), repeated.end(), 1)));
  return m;
}

}  // namespace hexadapt::dist
