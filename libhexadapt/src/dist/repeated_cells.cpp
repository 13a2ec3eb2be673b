// The repeated cells of dist::merge_pieces: every cell near other pieces goes, keyed by its
// sorted welded nodes, to the rank the key hashes to; that rank sees every cell of the key, sorts
// them in global order and flags each one whose piece differs from the key's first cell's.
#include <algorithm>
#include <array>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/merge_pieces.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt::dist {

namespace {

struct KeyedCell {
  std::array<std::int64_t, 8> key;  ///< sorted nodes; unused entries 0
  std::int64_t cell, piece;
};

std::vector<std::vector<std::int64_t>> flag_repeats(std::vector<KeyedCell> cells,
                                                    const Ranges& ranges, int n) {
  std::sort(cells.begin(), cells.end(), [](const KeyedCell& a, const KeyedCell& b) {
    return std::tie(a.key, a.cell) < std::tie(b.key, b.cell);
  });
  std::vector<std::vector<std::int64_t>> flagged(static_cast<std::size_t>(n));
  std::size_t first = 0;  // the start of the run of equal keys (the earliest such cell)
  for (std::size_t i = 1; i < cells.size(); ++i) {
    if (cells[i].key != cells[first].key) first = i;
    if (first < i && cells[i].piece != cells[first].piece)
      flagged[static_cast<std::size_t>(ranges.rank_of(cells[i].cell))].push_back(cells[i].cell);
  }
  return flagged;
}

}  // namespace

std::vector<char> repeated_cells(const Communicator& comm, const PiecesPart& part,
                                 const std::vector<std::int64_t>& welded,
                                 const std::vector<char>& near) {
  const auto npc = static_cast<std::size_t>(part.nodes_per_cell);
  if (npc > 8) throw InternalError("more than 8 nodes per cell");
  const std::size_t n_cells = part.cell_piece.size();
  const Ranges ranges = Ranges::of(comm, static_cast<std::int64_t>(n_cells));
  const std::int64_t first = ranges.first[static_cast<std::size_t>(comm.rank())];
  const int n = comm.size();
  std::vector<std::vector<KeyedCell>> out(static_cast<std::size_t>(n));
  for (std::size_t c = 0; c < n_cells; ++c) {
    const auto nodes = part.cells.begin() + static_cast<std::ptrdiff_t>(c * npc);
    if (!std::all_of(nodes, nodes + static_cast<std::ptrdiff_t>(npc),
                     [&](NodeId q) { return near[q.idx()] != 0; }))
      continue;  // a point far from other pieces: no other piece has this cell
    KeyedCell k{{}, first + static_cast<std::int64_t>(c), part.cell_piece[c]};
    for (std::size_t v = 0; v < npc; ++v) k.key[v] = welded[part.cells[c * npc + v].idx()];
    std::sort(k.key.begin(), k.key.begin() + static_cast<std::ptrdiff_t>(npc));
    out[static_cast<std::size_t>(rank_of_key(k.key.data(), npc, n))].push_back(k);
  }
  std::vector<char> repeated(n_cells, 0);
  for (const auto& from :
       all_to_all(comm, flag_repeats(joined(all_to_all(comm, std::move(out))), ranges, n)))
    for (const std::int64_t c : from) repeated[static_cast<std::size_t>(c - first)] = 1;
  return repeated;
}

}  // namespace hexadapt::dist
