#include "shared_nodes.h"

#include <algorithm>
#include <array>
#include <map>

#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt {

namespace {

// What the peers send about the nodes they share with this rank (put(b, v) per node v, after
// its key), by key, per peer. Every rank calls it.
template <class Put, class Get>
std::vector<std::map<std::vector<std::int64_t>,
                     decltype(std::declval<Get>()(std::declval<dist::Buffer&>()))>>
swapped(const dist::Communicator& comm, const SharedNodes& shared, Put put, Get get) {
  const std::vector<int>& peers = shared.peers;
  using Value = decltype(get(std::declval<dist::Buffer&>()));
  std::vector<dist::Buffer> mine(peers.size());
  for (std::size_t v = 0; v < shared.ranks.size(); ++v)
    for (int q : shared.ranks[v]) {
      dist::Buffer& b = mine[shared.peer_slot(q)];
      b.put_vector(shared.key[v]);
      put(b, NodeId(static_cast<index_t>(v)));
    }
  std::vector<dist::Buffer> theirs = dist::exchange(comm, peers, std::move(mine));
  std::vector<std::map<std::vector<std::int64_t>, Value>> out(peers.size());
  for (std::size_t k = 0; k < peers.size(); ++k)
    while (!theirs[k].done()) {
      std::vector<std::int64_t> key = theirs[k].template get_vector<std::int64_t>();
      Value value = get(theirs[k]);
      out[k].emplace(std::move(key), std::move(value));
    }
  return out;
}

// Sets the points of `nodes` and, for those without a target, their targets (their points).
template <class M>
void place(AdaptResult<M>& r, const std::vector<std::pair<NodeId, Vec3>>& nodes) {
  for (const auto& [v, p] : nodes) {
    r.mesh.set_point(v, p);
    if (!r.has_target[v]) r.target[v] = p;
  }
}

// Smooths the nodes of `r` around its failing cells that no other rank holds and that are not
// frozen, as the mending's local smoothing does: the cells a taken point left failing may
// pass again.
template <class M>
void repair_around_failing(AdaptResult<M>& r, const SharedNodes& shared,
                           const AdaptOptions& options) {
  const SizeCriterion size{options.min_edge, r.local_size};
  IdVector<NodeId, char> movable(static_cast<std::size_t>(r.mesh.n_nodes()), 0);
  for (const CellFailure& f : failing_cells(r.mesh, options.threshold, size))
    for (NodeId v : r.mesh.cell_nodes(f.cell))
      for (CellId c : r.mesh.node_cells(v))
        for (NodeId w : r.mesh.cell_nodes(c))
          movable[w] = shared.ranks[w.idx()].empty() && !r.sliding[w].frozen();
  SmoothOptions o = options.smooth;
  o.optimise_below = 1.0;
  o.floor = options.threshold;
  smooth(r.mesh, movable, r.sliding, o, nullptr, size);
}

// A point as a key: the ranks holding a node place it at the same point once shared.
std::array<double, 3> key(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

template <class M>
bool share_nodes(const dist::Communicator& comm, AdaptResult<M>& r, const SharedNodes& shared,
                 const AdaptOptions& options) {
  const auto points = swapped(
      comm, shared, [&](dist::Buffer& b, NodeId v) { b.put_point(r.mesh.point(v)); },
      [](dist::Buffer& b) { return b.get_point(); });
  const int me = comm.rank();
  bool named = true;  // every holder this rank names holds the node by the same name
  // Per group of holders (this rank and the others, as SharedNodes names them): the nodes,
  // with the points this rank takes from their lowest holder (0) or their highest (1).
  std::map<std::vector<int>, std::array<std::vector<std::pair<NodeId, Vec3>>, 2>> take;
  std::map<std::vector<int>, std::vector<std::pair<NodeId, Vec3>>> own;
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    if (shared.ranks[v.idx()].empty()) continue;
    const std::vector<int> group = shared.holders(v, me);
    own[group].emplace_back(v, r.mesh.point(v));
    auto& mine = take[group];
    for (const int q : {group.front(), group.back()}) {
      if (q == me) continue;
      const std::size_t k = shared.peer_slot(q);
      const auto at = points[k].find(shared.key[v.idx()]);
      if (at == points[k].end())
        named = false;
      else
        mine[q == group.front() ? 0 : 1].emplace_back(v, at->second);
    }
  }
  const SizeCriterion size{options.min_edge, r.local_size};
  const std::size_t failing = failing_cells(r.mesh, options.threshold, size).size();  // bad input's
  const auto passes = [&] {
    return failing_cells(r.mesh, options.threshold, size).size() <= failing;
  };
  std::vector<Vec3> before;
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) before.push_back(r.mesh.point(v));
  // Whether this rank's cells take each group's choices: the lowest holder's points, the
  // highest's, then each with this rank's free nodes around what then fails smoothed; every
  // rank's verdicts, on every rank.
  std::vector<std::int64_t> verdicts;  // per group: its size, its ranks, then 4 verdicts
  for (const auto& [group, choices] : take) {
    verdicts.push_back(static_cast<std::int64_t>(group.size()));
    verdicts.insert(verdicts.end(), group.begin(), group.end());
    for (int k = 0; k < 4; ++k) {
      place(r, choices[k % 2]);
      if (k >= 2) repair_around_failing(r, shared, options);
      verdicts.push_back(passes());
      for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) r.mesh.set_point(v, before[v.idx()]);
      place(r, own[group]);
    }
  }
  if (!dist::all_true(comm, named)) return false;
  // A group takes the first choice every rank of it can take.
  std::map<std::vector<int>, std::array<bool, 4>> can;
  const std::vector<std::int64_t> all = dist::all_gather_values(comm, verdicts);
  for (std::size_t k = 0; k < all.size();) {
    const auto n = static_cast<std::ptrdiff_t>(all[k]);
    const std::vector<int> group(all.begin() + static_cast<std::ptrdiff_t>(k) + 1,
                                 all.begin() + static_cast<std::ptrdiff_t>(k) + 1 + n);
    k += static_cast<std::size_t>(n) + 1;
    auto at = can.try_emplace(group, std::array<bool, 4>{true, true, true, true}).first;
    for (bool& c : at->second) c = all[k++] != 0 && c;  // every verdict read
  }
  bool fit = true, repair = false;
  for (const auto& [group, choices] : take) {
    const std::array<bool, 4>& ok = can.at(group);
    const auto k = static_cast<std::size_t>(std::find(ok.begin(), ok.end(), true) - ok.begin());
    fit = fit && k < ok.size();
    repair = repair || k >= 2;
    place(r, choices[k % 2]);
  }
  if (repair) repair_around_failing(r, shared, options);
  return dist::all_true(comm, fit && passes());
}

template <class M>
bool parts_meet(const dist::Communicator& comm, const M& mesh, const SharedNodes& shared,
                const std::vector<typename M::FaceNodes>& faces, const std::vector<int>& across) {
  const std::vector<int>& peers = shared.peers;
  using Face = std::vector<std::array<double, 3>>;
  std::vector<std::vector<Face>> toward(peers.size());
  bool fit = true;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto at = std::lower_bound(peers.begin(), peers.end(), across[f]);
    if (at == peers.end() || *at != across[f]) {
      fit = false;  // no node of the face is the rank across's
      continue;
    }
    Face corners;
    for (NodeId v : faces[f]) {
      const std::vector<int>& ranks = shared.ranks[v.idx()];
      fit = fit && std::binary_search(ranks.begin(), ranks.end(), across[f]);
      corners.push_back(key(mesh.point(v)));
    }
    std::sort(corners.begin(), corners.end());
    toward[static_cast<std::size_t>(at - peers.begin())].push_back(corners);
  }
  std::vector<dist::Buffer> mine(peers.size());
  std::vector<std::vector<double>> sent(peers.size());
  for (std::size_t k = 0; k < peers.size(); ++k) {
    std::sort(toward[k].begin(), toward[k].end());
    for (const Face& f : toward[k])
      for (const auto& p : f) sent[k].insert(sent[k].end(), p.begin(), p.end());
    mine[k].put_vector(sent[k]);
  }
  std::vector<dist::Buffer> theirs = dist::exchange(comm, peers, std::move(mine));
  for (std::size_t k = 0; k < peers.size(); ++k)
    fit = fit && theirs[k].get_vector<double>() == sent[k];
  return dist::all_true(comm, fit);
}

std::vector<std::pair<index_t, index_t>> nodes_counted_above(const dist::Communicator& comm,
                                                             const SharedNodes& shared) {
  const int me = comm.rank();
  std::vector<index_t> kept_id(shared.ranks.size(), -1);
  index_t kept = 0;
  for (std::size_t v = 0; v < shared.ranks.size(); ++v)
    if (shared.counts(NodeId(static_cast<index_t>(v)), me)) kept_id[v] = kept++;
  const std::vector<std::int64_t> counts =
      dist::all_gather_values(comm, std::vector<std::int64_t>{kept});
  const auto ids = swapped(
      comm, shared, [&](dist::Buffer& b, NodeId v) { b.put(kept_id[v.idx()]); },
      [](dist::Buffer& b) { return b.get<index_t>(); });
  std::vector<std::pair<index_t, index_t>> above;
  for (std::size_t v = 0; v < shared.ranks.size(); ++v) {
    if (kept_id[v] >= 0) continue;
    const int q = shared.ranks[v].back();
    const std::size_t k = shared.peer_slot(q);
    const auto at = ids[k].find(shared.key[v]);
    if (at == ids[k].end() || at->second < 0)
      throw InternalError("a shared node is not counted by the highest rank holding it");
    index_t past = at->second;  // past this rank's points: the pieces between, then q's id
    for (int between = me + 1; between < q; ++between)
      past += static_cast<index_t>(counts[static_cast<std::size_t>(between)]);
    above.emplace_back(static_cast<index_t>(v), past);
  }
  return above;
}

template bool share_nodes<QuadMesh>(const dist::Communicator&, AdaptResult<QuadMesh>&,
                                    const SharedNodes&, const AdaptOptions&);
template bool share_nodes<HexMesh>(const dist::Communicator&, AdaptResult<HexMesh>&,
                                   const SharedNodes&, const AdaptOptions&);
template bool parts_meet<QuadMesh>(const dist::Communicator&, const QuadMesh&, const SharedNodes&,
                                   const std::vector<QuadMesh::FaceNodes>&,
                                   const std::vector<int>&);
template bool parts_meet<HexMesh>(const dist::Communicator&, const HexMesh&, const SharedNodes&,
                                  const std::vector<HexMesh::FaceNodes>&, const std::vector<int>&);

}  // namespace hexadapt
