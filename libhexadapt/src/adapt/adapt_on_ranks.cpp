#include "hexadapt/adapt/adapt_on_ranks.h"

#include <algorithm>
#include <variant>

#include "cut_bands.h"
#include "held_part.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/dist/routing.h"
#include "own_part.h"
#include "rank_decisions.h"
#include "shared_nodes.h"

namespace hexadapt {

namespace {

// The rings of cells on each side of a cut whose nodes the second pass moves on.
constexpr int cut_rings = 4;

// A rank's part of the mesh (own_part.h) and the ranks whose parts hold its frozen nodes (a
// cut's nodes and their copies) too.
template <class M>
struct RankMesh {
  OwnPart<M> part;
  SharedNodes shared;
  std::vector<int> across;         ///< per face of part.cut_faces, the rank whose part is across it
  IdVector<NodeId, char> counted;  ///< the nodes this rank counts (SharedNodes::counts)
};
using AnyRankMesh = std::variant<RankMesh<QuadMesh>, RankMesh<HexMesh>>;

// The part of `r` that comes from the rank's own cells, and who else holds its frozen nodes:
// the owners of the input cells around them (a slab's: the rank beside its cut).
template <class M>
RankMesh<M> rank_mesh(const dist::Communicator& comm, AdaptResult<M> r, const HeldPart& s,
                      const dist::Block& block) {
  RankMesh<M> m;
  m.part = own_part(std::move(r), {s.first_cell, s.first_cell + s.own_cells}, s.first_nodes);
  const AdaptResult<M>& own = m.part.result;
  const auto n = static_cast<std::size_t>(own.mesh.n_nodes());
  const int me = comm.rank();
  m.shared.ranks.resize(n);
  m.shared.key.resize(n);
  const auto owner = [&](CellId c) { return s.cell_owner[c.idx()]; };
  for (NodeId v : id_range<NodeId>(own.mesh.n_nodes())) {
    if (v.idx() >= own.sliding.size() || !own.sliding[v].frozen()) continue;
    std::vector<std::int64_t>& key = m.shared.key[v.idx()];
    std::vector<int>& ranks = m.shared.ranks[v.idx()];
    for (CellId c : m.part.around[v.idx()]) {
      key.push_back(block.global(c));
      if (owner(c) != me) ranks.push_back(owner(c));
    }
    std::sort(key.begin(), key.end());
    key.insert(key.begin(), block.global(own.node_origin[v]));
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  }
  for (int q : s.cell_owner)
    if (q != me) m.shared.peers.push_back(q);
  std::sort(m.shared.peers.begin(), m.shared.peers.end());
  m.shared.peers.erase(std::unique(m.shared.peers.begin(), m.shared.peers.end()),
                       m.shared.peers.end());
  for (CellId c : m.part.cut_across) m.across.push_back(owner(c));
  m.counted.assign(n, 0);
  for (NodeId v : id_range<NodeId>(own.mesh.n_nodes())) m.counted[v] = m.shared.counts(v, me);
  return m;
}

// False on every rank when the mending ran out of runs with cells still failing on some rank
// (the last run then carves the layers where they fail, each rank on its own): with the cells
// around the cuts pillowed, the cells beside the frozen cuts can keep failing where one
// process's mending ends (the vortex 64^3 on 3 ranks: 1-2 cells failing after each of 12
// runs, every layer carved away, 94 % of one process's nodes near their interface; 98 % with
// the cuts unpillowed). Every rank calls it.
template <class M>
bool mended(const dist::Communicator& comm, const AdaptResult<M>& r, const AdaptOptions& options) {
  const bool ran_out = options.mend_rounds > 0 &&
                       r.mend_failing.size() == static_cast<std::size_t>(options.mend_rounds) &&
                       r.mend_failing.back() > 0;
  return dist::all_true(comm, !ran_out);
}

// The worst of every rank's failing cells (ids of the whole run), on every rank: the ten that
// one process would list among them.
std::vector<CellFailure> worst_on_ranks(const dist::Communicator& comm,
                                        const std::vector<CellFailure>& mine) {
  constexpr std::size_t fields = 7;
  std::vector<double> packed;
  for (const CellFailure& f : mine)
    packed.insert(packed.end(),
                  {static_cast<double>(f.cell.value()), f.scaled_jacobian, f.shortest_edge,
                   f.min_length, f.centroid.x(), f.centroid.y(), f.centroid.z()});
  const std::vector<double> all = dist::all_gather_values(comm, packed);
  std::vector<CellFailure> failures;
  for (std::size_t k = 0; k + fields <= all.size(); k += fields) {
    CellFailure f;
    f.cell = CellId(static_cast<index_t>(all[k]));
    f.scaled_jacobian = all[k + 1];
    f.shortest_edge = all[k + 2];
    f.min_length = all[k + 3];
    f.centroid = Vec3(all[k + 4], all[k + 5], all[k + 6]);
    failures.push_back(f);
  }
  return worst_failures(std::move(failures), 10);
}

// The worst failing cells of the output (ids shifted by the cells of the ranks before, as in
// the gathered mesh).
std::vector<CellFailure> output_failures(const dist::Communicator& comm,
                                         std::vector<CellFailure> mine, index_t n_cells) {
  const std::vector<std::int64_t> counts =
      dist::all_gather_values(comm, std::vector<std::int64_t>{n_cells});
  index_t shift = 0;
  for (int r = 0; r < comm.rank(); ++r)
    shift += static_cast<index_t>(counts[static_cast<std::size_t>(r)]);
  for (CellFailure& f : mine) f.cell = CellId(f.cell.value() + shift);
  return worst_on_ranks(comm, mine);
}

// Whether some rank stopped on bad input cells (the guaranteed method does not start from
// them): then the result names every rank's own ones by their ids in the whole grid, as one
// process names them, and the worst of them. Every rank calls it.
bool stopped_on_input(const dist::Communicator& comm, const AnyAdaptResult& adapted,
                      const HeldPart& s, const dist::Block& block, RankAdaptResult& result) {
  const index_t first = s.first_cell, end = first + s.own_cells;
  const auto own = [&](CellId c) { return c.value() >= first && c.value() < end; };
  bool stopped = false;
  std::vector<std::int64_t> mine;
  std::visit(
      [&](const auto& r) {
        stopped = r.stopped_bad_input;
        for (CellId c : r.bad_input_cells)
          if (own(c)) mine.push_back(block.global(c));
        std::vector<CellFailure> failures;
        for (CellFailure f : r.stopped_bad_input ? r.failures : std::vector<CellFailure>{})
          if (own(f.cell)) {
            f.cell = CellId(static_cast<index_t>(block.global(f.cell)));
            failures.push_back(f);
          }
        result.failures = worst_on_ranks(comm, failures);
      },
      adapted);
  result.bad_input_cells = dist::all_gather_values(comm, mine);
  std::sort(result.bad_input_cells.begin(), result.bad_input_cells.end());
  return !dist::all_true(comm, !stopped);
}

// Every rank's figures, in rank order.
std::vector<AdaptFigures> all_figures(const dist::Communicator& comm, const AdaptFigures& f) {
  dist::Buffer b;
  for (index_t n : {f.cells_in, f.cells, f.nodes, f.interface_nodes, f.reached, f.near_interface,
                    f.blocked, f.frozen_blocked, f.below_threshold, f.inverted, f.below_min_edge})
    b.put(n);
  for (double x : {f.dist_init, f.dist_final, f.surface_dist_init, f.surface_dist_final,
                   f.min_quality, f.min_edge_ratio, f.input_min_quality, f.seconds,
                   f.farthest.distance, f.farthest.local_size})
    b.put(x);
  b.put(f.loops);
  b.put(static_cast<char>(f.farthest.valid));
  b.put_point(f.farthest.position);
  std::vector<AdaptFigures> all;
  for (dist::Buffer& r : dist::all_gather(comm, b)) {
    AdaptFigures g;
    for (index_t* n : {&g.cells_in, &g.cells, &g.nodes, &g.interface_nodes, &g.reached,
                       &g.near_interface, &g.blocked, &g.frozen_blocked, &g.below_threshold,
                       &g.inverted, &g.below_min_edge})
      *n = r.get<index_t>();
    for (double* x : {&g.dist_init, &g.dist_final, &g.surface_dist_init, &g.surface_dist_final,
                      &g.min_quality, &g.min_edge_ratio, &g.input_min_quality, &g.seconds,
                      &g.farthest.distance, &g.farthest.local_size})
      *x = r.get<double>();
    g.loops = r.get<int>();
    g.farthest.valid = r.get<char>() != 0;
    g.farthest.position = r.get_point();
    all.push_back(g);
  }
  return all;
}

// Every rank's run, in rank order.
template <class M>
std::vector<RankRun> all_runs(const dist::Communicator& comm, const AdaptResult<M>& r) {
  dist::Buffer b;
  b.put(static_cast<int>(r.layers));
  b.put_vector(r.mend_failing);
  b.put(r.n_interface_layer_cells);
  b.put(r.n_cavities_published);
  std::vector<RankRun> all;
  for (dist::Buffer& g : dist::all_gather(comm, b)) {
    RankRun run;
    run.layers = static_cast<LayerStrategy>(g.get<int>());
    run.mend_failing = g.get_vector<index_t>();
    run.interface_layer_cells = g.get<index_t>();
    run.cavities_published = g.get<index_t>();
    all.push_back(run);
  }
  return all;
}

// Adapts the part, its cuts pillowed, unless the mending ran out of runs, or the ranks holding
// a cut's nodes laid different layers around them, or placed their copies too far apart to
// take each other's points: then unpillowed. Every rank calls it.
AnyRankMesh adapt_part(HeldPart& part, AdaptOptions& options, const dist::Distribution& where,
                       RankAdaptResult& result) {
  AnyRankMesh mesh;
  for (const bool pillow : {true, false}) {
    options.boundary.pillow_frozen = pillow;
    mesh = AnyRankMesh();  // a first run's part is not kept through the second
    AnyAdaptResult adapted;
    dist::on_every_rank(where.comm,
                        [&] { adapted = adapt(part.grid, options, nullptr, &part.targets); });
    result.stopped_bad_input = stopped_on_input(where.comm, adapted, part, where.block, result);
    std::visit(
        [&](auto& r) { mesh = rank_mesh(where.comm, std::move(r), part, where.block); }, adapted);
    if (result.stopped_bad_input) break;
    const bool met = pillow && std::visit(
                                   [&](auto& m) {
                                     return mended(where.comm, m.part.result, options) &&
                                            share_nodes(where.comm, m.part.result, m.shared,
                                                        options) &&
                                            parts_meet(where.comm, m.part.result.mesh, m.shared,
                                                       m.part.cut_faces, m.across);
                                   },
                                   mesh);
    result.cut_layers = met ? CutLayers::pillowed : CutLayers::unpillowed;
    if (met || !pillow) break;
  }
  return mesh;
}

}  // namespace

std::string to_string(CutLayers layers) {
  switch (layers) {
    case CutLayers::pillowed: return "pillowed";
    case CutLayers::unpillowed: return "unpillowed";
    case CutLayers::none: return "none";
  }
  return "";
}

RankAdaptResult adapt(AssignedGrid&& held, const AdaptOptions& given,
                      const dist::Distribution& where, const std::optional<SlabPlace>& slab) {
  const dist::Communicator& comm = where.comm;
  dist::on_every_rank(comm, [&] {
    if (given.method != AdaptMethod::guaranteed)
      throw OptionError("{method} " + to_string(given.method) +
                        " runs on one process: on several ranks, guaranteed");
    held.require_assigned("adapt");
  });
  Timer clock;
  RankAdaptResult result;
  HeldPart part = held_part(std::move(held), where, slab, given);
  AdaptOptions options = given;
  options.boundary.frozen = part.frozen;
  options.ranks = rank_decisions(comm, part, where.block);
  AnyRankMesh mesh = adapt_part(part, options, where, result);
  const int dim = std::holds_alternative<HexMesh>(part.grid.mesh) ? 3 : 2;
  part.grid = AssignedGrid();
  const double adapt_seconds = clock.seconds();
  result.times.emplace_back("adapt", adapt_seconds);
  // In 2D the layers are cavities, and no cavity holds a cut's node: nothing is laid across.
  if (result.cut_layers == CutLayers::pillowed && dim == 2) result.cut_layers = CutLayers::none;
  std::visit(
      [&](auto& m) {
        auto& r = m.part.result;
        if (!result.stopped_bad_input) {
          clock.restart();
          resume_across_cuts(comm, r, m.shared, cut_rings, options);
          result.times.emplace_back("cuts", clock.seconds());
          result.failures = output_failures(comm, r.failures, r.mesh.n_cells());
          result.counted_above = nodes_counted_above(comm, m.shared);
        }
        result.ranks =
            all_figures(comm, adapt_figures(r, m.counted, part.own_cells, adapt_seconds));
        result.runs = all_runs(comm, r);
        result.part = std::move(r);
      },
      mesh);
  result.total = summed(result.ranks);
  return result;
}

}  // namespace hexadapt
