#include "rank_decisions.h"

#include <algorithm>
#include <memory>

#include "hexadapt/dist/routing.h"

namespace hexadapt {

namespace {

// Sends to[k] (global ids of cells) to peers[k]; what the peers send, in this rank's ids.
std::vector<CellId> received_cells(const dist::Communicator& comm, const std::vector<int>& peers,
                                   std::vector<std::vector<std::int64_t>> to,
                                   const dist::Block& block) {
  std::vector<dist::Buffer> out(peers.size());
  for (std::size_t k = 0; k < peers.size(); ++k) out[k].put_vector(to[k]);
  std::vector<CellId> cells;
  for (dist::Buffer& b : dist::exchange(comm, peers, std::move(out)))
    for (std::int64_t g : b.get_vector<std::int64_t>()) cells.push_back(block.local_cell(g));
  return cells;
}

// Shared by the copies of the options the pipeline makes: the rank's own cells (global ids,
// increasing), the other ranks holding each, and every rank it exchanges cells with.
struct Holders {
  std::vector<std::int64_t> own;
  std::vector<std::vector<int>> of_own;
  std::vector<int> peers;
  std::size_t slot(int q) const {
    return static_cast<std::size_t>(std::lower_bound(peers.begin(), peers.end(), q) -
                                    peers.begin());
  }
};

std::shared_ptr<const Holders> holders(const dist::Communicator& comm, const HeldPart& s,
                                       const dist::Block& block) {
  const auto held = std::make_shared<Holders>();
  std::vector<std::int64_t> ghosts;
  for (CellId c : id_range<CellId>(static_cast<index_t>(s.cell_owner.size())))
    (s.cell_owner[c.idx()] == comm.rank() ? held->own : ghosts).push_back(block.global(c));
  std::sort(ghosts.begin(), ghosts.end());  // a slab's are in order already, a list's too
  held->of_own = dist::other_holders(comm, held->own, ghosts);
  for (const std::vector<int>& q : held->of_own)
    held->peers.insert(held->peers.end(), q.begin(), q.end());
  for (int q : s.cell_owner)
    if (q != comm.rank()) held->peers.push_back(q);
  std::sort(held->peers.begin(), held->peers.end());
  held->peers.erase(std::unique(held->peers.begin(), held->peers.end()), held->peers.end());
  return held;
}

}  // namespace

RankDecisions rank_decisions(const dist::Communicator& comm, const HeldPart& s,
                             const dist::Block& block) {
  const std::shared_ptr<const Holders> held = holders(comm, s, block);
  RankDecisions d;
  d.left_out = [&comm, &s, &block, held](std::vector<CellId>& cells) {
    const Holders& h = *held;
    const bool mine = !cells.empty();
    std::vector<std::vector<std::int64_t>> to(h.peers.size());
    for (CellId c : cells)
      if (s.cell_owner[c.idx()] != comm.rank())
        to[h.slot(s.cell_owner[c.idx()])].push_back(block.global(c));
    std::vector<CellId> failing = received_cells(comm, h.peers, std::move(to), block);
    for (CellId c : cells)
      if (s.cell_owner[c.idx()] == comm.rank()) failing.push_back(c);
    std::sort(failing.begin(), failing.end());
    failing.erase(std::unique(failing.begin(), failing.end()), failing.end());
    to.assign(h.peers.size(), {});
    for (CellId c : failing) {
      const std::int64_t g = block.global(c);
      const auto at = std::lower_bound(h.own.begin(), h.own.end(), g) - h.own.begin();
      for (int q : h.of_own[static_cast<std::size_t>(at)]) to[h.slot(q)].push_back(g);
    }
    for (std::vector<std::int64_t>& ids : to) std::sort(ids.begin(), ids.end());
    std::vector<CellId> back = received_cells(comm, h.peers, std::move(to), block);
    cells.insert(cells.end(), failing.begin(), failing.end());
    cells.insert(cells.end(), back.begin(), back.end());
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return !dist::all_true(comm, !mine);  // some rank's run left a cell failing
  };
  d.add_up = summed_over_ranks(comm);
  return d;
}

}  // namespace hexadapt
