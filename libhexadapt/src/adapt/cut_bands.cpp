#include "cut_bands.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/quad_mesh.h"
#include "hexadapt/mesh/unit_frame.h"
#include "pipeline_steps.h"

namespace hexadapt {

namespace {

constexpr index_t unset = -1;

// The cells within `rings` rings of cells of a cut's nodes, increasing, and each node's ring
// (unset beyond): a node of ring < rings has every cell of its own in the band.
template <class M>
std::pair<std::vector<CellId>, std::vector<index_t>> band_of(const M& mesh,
                                                             const std::vector<NodeId>& cut,
                                                             int rings) {
  std::vector<index_t> ring(static_cast<std::size_t>(mesh.n_nodes()), unset);
  std::vector<char> in(static_cast<std::size_t>(mesh.n_cells()), 0);
  std::vector<CellId> cells;
  std::vector<NodeId> front = cut;
  for (NodeId v : cut) ring[v.idx()] = 0;
  for (index_t step = 1; step <= rings; ++step) {
    std::vector<NodeId> next;
    for (NodeId v : front)
      for (CellId c : mesh.node_cells(v)) {
        if (in[c.idx()]) continue;
        in[c.idx()] = 1;
        cells.push_back(c);
        for (NodeId w : mesh.cell_nodes(c))
          if (ring[w.idx()] == unset) {
            ring[w.idx()] = step;
            next.push_back(w);
          }
      }
    front = std::move(next);
  }
  std::sort(cells.begin(), cells.end());
  return {cells, ring};
}

void put_constraint(dist::Buffer& b, const NodeConstraint& c) {
  b.put(c.n_normals());
  for (int k = 0; k < c.n_normals(); ++k) b.put_point(c.normal(k));
  b.put(static_cast<char>(c.frozen()));
}

NodeConstraint get_constraint(dist::Buffer& b) {
  NodeConstraint c;
  const int n = b.get<int>();
  for (int k = 0; k < n; ++k) c.add(b.get_point());
  if (b.get<char>()) c.freeze();
  return c;
}

// The ranks of `group` (increasing) that hold v besides this one.
int others_in(const std::vector<int>& group, const std::vector<int>& holders) {
  int n = 0;
  for (int q : holders) n += std::binary_search(group.begin(), group.end(), q);
  return n;
}

// Whether every rank holding v (this one and `holders`) is in `group`.
bool within(const std::vector<int>& group, const std::vector<int>& holders) {
  return others_in(group, holders) == static_cast<int>(holders.size());
}

// A rank's half of the band of `group`: its cells near the nodes the group's ranks alone hold,
// and their nodes, with what the moves need. The nodes it may move are let go (the band adds
// the boundary of the shared ones); the nodes a rank outside the group holds stay frozen.
template <class M>
dist::Buffer half_band(const AdaptResult<M>& r, const SharedNodes& shared,
                       const std::vector<int>& group, int me, int rings) {
  const M& mesh = r.mesh;
  std::vector<NodeId> seeds;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (!shared.ranks[v.idx()].empty() && shared.holders(v, me) == group) seeds.push_back(v);
  const auto [cells, ring] = band_of(mesh, seeds, rings);
  std::vector<index_t> slot(static_cast<std::size_t>(mesh.n_nodes()), unset);
  std::vector<NodeId> nodes;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (ring[v.idx()] != unset) {
      slot[v.idx()] = static_cast<index_t>(nodes.size());
      nodes.push_back(v);
    }
  dist::Buffer b;
  b.put(static_cast<std::uint64_t>(nodes.size()));
  for (NodeId v : nodes) {
    const std::vector<int>& others = shared.ranks[v.idx()];
    const bool movable = ring[v.idx()] < rings && within(group, others);
    b.put(v.value());
    b.put(others_in(group, others));  // the other halves holding it, matched by its point
    b.put(static_cast<char>(movable));
    b.put_point(mesh.point(v));
    b.put(r.has_target[v]);
    b.put_point(r.target[v]);
    put_constraint(b, movable ? r.sliding[v].unfrozen() : r.sliding[v]);
  }
  b.put(static_cast<std::uint64_t>(cells.size()));
  for (CellId c : cells) {
    for (NodeId v : mesh.cell_nodes(c)) b.put(slot[v.idx()]);
    b.put(r.local_size[c]);
  }
  return b;
}

// The band mesh every rank of a group builds from the halves (in rank order), the same on each.
template <class M>
struct Band {
  M mesh;
  Targets targets;
  IdVector<NodeId, NodeConstraint> sliding;
  SizeCriterion size;
  std::vector<NodeId> movable;
  /// Per half: each of its nodes' local id on its rank and id in the band.
  std::vector<std::vector<std::pair<NodeId, NodeId>>> ids;
};

// A point as a key: the ranks holding a node place it at the same point.
std::array<double, 3> key(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

template <class M>
Band<M> joined(std::vector<dist::Buffer> halves, double min_edge, const BoundaryOptions& bo) {
  Band<M> band;
  std::vector<Vec3> points;
  std::vector<typename M::CellNodes> cells;
  // The band id of each node several halves hold, from the first half holding it, by its point.
  std::map<std::array<double, 3>, index_t> shared_band;
  // Per band node: the halves that hold it besides the first, those that sent it since, and
  // whether every one of them lets it move.
  std::vector<int> others, seen;
  std::vector<char> movable;
  for (dist::Buffer& b : halves) {
    std::vector<std::pair<NodeId, NodeId>>& ids = band.ids.emplace_back();
    const auto n = b.get<std::uint64_t>();
    std::vector<index_t> to(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      const NodeId local(b.get<index_t>());
      const int in_others = b.get<int>();
      const bool move = b.get<char>() != 0;
      const Vec3 p = b.get_point();
      const char has = b.get<char>();
      const Vec3 target = b.get_point();
      const NodeConstraint c = get_constraint(b);
      const auto at = in_others > 0 ? shared_band.find(key(p)) : shared_band.end();
      if (at != shared_band.end()) {
        to[i] = at->second;
        const auto k = static_cast<std::size_t>(at->second);
        seen[k] += 1;
        movable[k] = movable[k] && move;
      } else {
        to[i] = static_cast<index_t>(points.size());
        points.push_back(p);
        band.targets.has.push_back(has);
        band.targets.position.push_back(target);
        band.sliding.push_back(c);
        others.push_back(in_others);
        seen.push_back(0);
        movable.push_back(move);
        if (in_others > 0) shared_band.emplace(key(p), to[i]);
      }
      ids.emplace_back(local, NodeId(to[i]));
    }
    const auto m = b.get<std::uint64_t>();
    for (std::uint64_t i = 0; i < m; ++i) {
      typename M::CellNodes nodes;
      for (NodeId& v : nodes) v = NodeId(to[static_cast<std::size_t>(b.get<index_t>())]);
      cells.push_back(nodes);
      band.size.local_size.push_back(b.get<double>());
    }
  }
  band.size.min_edge = min_edge;
  band.mesh = M(std::move(points), std::move(cells));
  const auto boundary = boundary_constraints(band.mesh, bo.without_frozen());
  for (NodeId v : id_range<NodeId>(band.mesh.n_nodes())) {
    const std::size_t k = v.idx();
    if (others[k] > 0) {  // a cut's node: the band's boundary is the domain's there
      NodeConstraint c = boundary[v];
      c.add(band.sliding[v]);
      band.sliding[v] = c;
    }
    // A node moves when every rank holding it sent all its cells around it.
    if (movable[k] && seen[k] == others[k])
      band.movable.push_back(v);
    else
      band.sliding[v].freeze();
  }
  band.targets.interface = band.sliding;
  return band;
}

// Moves the band's nodes on in the frame the pipeline runs in (mesh/unit_frame.h), so that
// the moves are the same in any unit; a node that did not move keeps its bits.
template <class M>
void move_in_unit_frame(Band<M>& band, const AdaptOptions& options) {
  const UnitFrame frame = unit_frame(band.mesh);
  M local = to_local(band.mesh, frame);
  Targets targets = band.targets;
  for (Vec3& t : targets.position) t = frame.to_local(t);
  SizeCriterion size = band.size;
  for (double& h : size.local_size) h = frame.to_local(h);
  const M before = local;
  resume_moves(local, targets, band.sliding, size, options);
  for (NodeId v : id_range<NodeId>(local.n_nodes()))
    if (local.point(v) != before.point(v)) band.mesh.set_point(v, frame.to_world(local.point(v)));
}

// The band's new positions and figures onto the rank's own nodes of half `h`.
template <class M>
void take_back(const Band<M>& band, std::size_t h, AdaptResult<M>& r, double near_interface) {
  std::vector<char> movable(static_cast<std::size_t>(band.mesh.n_nodes()), 0);
  for (NodeId v : band.movable) movable[v.idx()] = 1;
  for (const auto& [local, at] : band.ids[h]) {
    if (!movable[at.idx()]) continue;
    const Vec3 p = band.mesh.point(at);
    r.mesh.set_point(local, p);
    r.has_target[local] = band.targets.has[at];
    r.target[local] = band.targets.has[at] ? band.targets.position[at] : p;
    r.sliding[local] = band.sliding[at];
    r.distance[local] = (p - r.target[local]).norm();
    r.surface_distance[local] =
        band.targets.has[at] ? surface_distance(p, r.target[local], band.sliding[at]) : 0.0;
    const bool near =
        !band.targets.has[at] ||
        r.surface_distance[local] <= near_interface * node_local_size(band.mesh, at, band.size);
    r.near_interface[local] = near;
    r.blocked[local] = static_cast<char>(near ? BlockReason::none : BlockReason::quality);
  }
}

// Every rank's groups (the ranks holding some node together, SharedNodes), each once, in
// rounds in which no rank is in two groups: each group in the first round none of its ranks
// is busy in, taken by size then ranks. The same on every rank. Every rank calls it.
std::vector<std::vector<std::vector<int>>> group_rounds(const dist::Communicator& comm,
                                                        const SharedNodes& shared) {
  const int me = comm.rank();
  std::set<std::vector<int>> own;  // this rank's groups, each once
  for (NodeId v : id_range<NodeId>(static_cast<index_t>(shared.ranks.size())))
    if (!shared.ranks[v.idx()].empty()) own.insert(shared.holders(v, me));
  std::vector<std::int64_t> mine;  // each group as its size, then its ranks
  for (const std::vector<int>& g : own) {
    mine.push_back(static_cast<std::int64_t>(g.size()));
    mine.insert(mine.end(), g.begin(), g.end());
  }
  const std::vector<std::int64_t> all = dist::all_gather_values(comm, mine);
  std::vector<std::vector<int>> groups;
  for (std::size_t k = 0; k < all.size(); k += static_cast<std::size_t>(all[k]) + 1)
    groups.emplace_back(
        all.begin() + static_cast<std::ptrdiff_t>(k + 1),
        all.begin() + static_cast<std::ptrdiff_t>(k + 1) + static_cast<std::ptrdiff_t>(all[k]));
  std::sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  std::vector<std::vector<std::vector<int>>> rounds;
  std::vector<std::vector<char>> busy;  // per round, per rank
  for (std::vector<int>& g : groups) {
    std::size_t k = 0;
    const auto free_in = [&](std::size_t round) {
      return std::none_of(g.begin(), g.end(),
                          [&](int q) { return busy[round][static_cast<std::size_t>(q)] != 0; });
    };
    while (k < rounds.size() && !free_in(k)) ++k;
    if (k == rounds.size()) {
      rounds.emplace_back();
      busy.emplace_back(static_cast<std::size_t>(comm.size()), 0);
    }
    for (int q : g) busy[k][static_cast<std::size_t>(q)] = 1;
    rounds[k].push_back(std::move(g));
  }
  return rounds;
}

}  // namespace

template <class M>
void resume_across_cuts(const dist::Communicator& comm, AdaptResult<M>& r,
                        const SharedNodes& shared, int rings, const AdaptOptions& options) {
  AdaptOptions moves = options;
  moves.boundary.frozen = {};
  moves.progress = nullptr;
  const int me = comm.rank();
  for (const auto& round : group_rounds(comm, shared))
    for (const std::vector<int>& group : round) {
      const auto at = std::lower_bound(group.begin(), group.end(), me);
      if (at == group.end() || *at != me) continue;
      std::vector<int> peers;
      for (int q : group)
        if (q != me) peers.push_back(q);
      dist::Buffer half = half_band(r, shared, group, me, rings);
      std::vector<dist::Buffer> theirs =
          dist::exchange(comm, peers, std::vector<dist::Buffer>(peers.size(), half));
      const auto h = static_cast<std::size_t>(at - group.begin());
      theirs.insert(theirs.begin() + static_cast<std::ptrdiff_t>(h), std::move(half));
      Band<M> band = joined<M>(std::move(theirs), options.min_edge, options.boundary);
      move_in_unit_frame(band, moves);
      take_back(band, h, r, options.near_interface);
    }
  detail::count_cells(r, SizeCriterion{options.min_edge, r.local_size}, options.threshold);
}

template void resume_across_cuts<QuadMesh>(const dist::Communicator&, AdaptResult<QuadMesh>&,
                                           const SharedNodes&, int, const AdaptOptions&);
template void resume_across_cuts<HexMesh>(const dist::Communicator&, AdaptResult<HexMesh>&,
                                          const SharedNodes&, int, const AdaptOptions&);

}  // namespace hexadapt
