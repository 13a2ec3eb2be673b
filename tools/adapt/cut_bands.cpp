#include "cut_bands.h"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/quad_mesh.h"
#include "hexadapt/mesh/unit_frame.h"

namespace hexadapt::cli {

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

// A rank's half of a band: its cells near the cut and their nodes, with what the moves need.
// The nodes it moves are let go (the band adds the boundary of the cut's); the nodes of the
// slab's other cut stay frozen.
template <class M>
dist::Buffer half_band(const SlabMesh<M>& slab, bool top, int rings) {
  const AdaptResult<M>& r = slab.result;
  const M& mesh = r.mesh;
  const CutSide side = top ? CutSide::above : CutSide::below;
  std::vector<NodeId> cut;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (slab.cut[v] == side) cut.push_back(v);
  const auto [cells, ring] = band_of(mesh, cut, rings);
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
    const bool on_cut = slab.cut[v] == side;
    const bool movable = ring[v.idx()] < rings && (on_cut || slab.cut[v] == CutSide::none);
    b.put(v.value());
    b.put(static_cast<char>(on_cut));
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

// The band mesh both ranks build from the two halves (the lower's first), the same on each.
template <class M>
struct Band {
  M mesh;
  Targets targets;
  IdVector<NodeId, NodeConstraint> sliding;
  SizeCriterion size;
  std::vector<NodeId> movable;
  /// Per half: each of its nodes' local id on its rank and id in the band.
  std::array<std::vector<std::pair<NodeId, NodeId>>, 2> ids;
};

// A point as a key: both ranks place a cut's nodes and their copies at the same points.
std::array<double, 3> key(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

template <class M>
Band<M> joined(std::array<dist::Buffer, 2> halves, double min_edge, const BoundaryOptions& bo) {
  Band<M> band;
  std::vector<Vec3> points;
  std::vector<typename M::CellNodes> cells;
  // The band id of each node of the cut, from the lower half, by its point.
  std::map<std::array<double, 3>, index_t> cut_band;
  std::vector<char> is_cut, movable;
  for (int h = 0; h < 2; ++h) {
    dist::Buffer& b = halves[static_cast<std::size_t>(h)];
    const auto n = b.get<std::uint64_t>();
    std::vector<index_t> to(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      const NodeId local(b.get<index_t>());
      const bool on_cut = b.get<char>() != 0;
      const bool move = b.get<char>() != 0;
      const Vec3 p = b.get_point();
      const char has = b.get<char>();
      const Vec3 target = b.get_point();
      const NodeConstraint c = get_constraint(b);
      if (h == 1 && on_cut) {  // the lower half has it
        const auto at = cut_band.find(key(p));
        if (at == cut_band.end())
          throw InternalError("a node of a cut on the rank above is not the rank below's");
        to[i] = at->second;
      } else {
        to[i] = static_cast<index_t>(points.size());
        points.push_back(p);
        band.targets.has.push_back(has);
        band.targets.position.push_back(target);
        band.sliding.push_back(c);
        is_cut.push_back(on_cut);
        movable.push_back(move);
        if (on_cut) cut_band.emplace(key(p), to[i]);
      }
      band.ids[static_cast<std::size_t>(h)].emplace_back(local, NodeId(to[i]));
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
    if (is_cut[v.idx()]) {
      NodeConstraint c = boundary[v];
      c.add(band.sliding[v]);
      band.sliding[v] = c;
    }
    if (movable[v.idx()])
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
void take_back(const Band<M>& band, int h, AdaptResult<M>& r, double near_interface) {
  std::vector<char> movable(static_cast<std::size_t>(band.mesh.n_nodes()), 0);
  for (NodeId v : band.movable) movable[v.idx()] = 1;
  for (const auto& [local, at] : band.ids[static_cast<std::size_t>(h)]) {
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

// The figures of the rank's cells after the moves: least quality, shortest edge, failing cells.
template <class M>
void recount_cells(AdaptResult<M>& r, const AdaptOptions& options) {
  SizeCriterion size{options.min_edge, r.local_size};
  r.min_quality = min_quality(r.mesh);
  r.min_edge_ratio = min_edge_ratio(r.mesh, size);
  std::vector<CellFailure> failures = failing_cells(r.mesh, options.threshold, size);
  r.n_below_threshold = r.n_below_min_edge = r.n_inverted = 0;
  for (const CellFailure& f : failures) {
    r.n_below_threshold += f.shape_failed(options.threshold);
    r.n_below_min_edge += f.size_failed();
    r.n_inverted += f.scaled_jacobian <= 0;
  }
  r.failures = worst_failures(std::move(failures), 10);
}

// The part's faces on one cut, each as its corners' points sorted, in order, as numbers.
template <class M>
std::vector<double> faces_on(const SlabMesh<M>& slab, CutSide side) {
  std::vector<std::vector<std::array<double, 3>>> faces;
  for (const typename M::FaceNodes& f : slab.cut_faces[side == CutSide::below ? 0 : 1]) {
    std::vector<std::array<double, 3>> corners;
    for (NodeId v : f) corners.push_back(key(slab.result.mesh.point(v)));
    std::sort(corners.begin(), corners.end());
    faces.push_back(corners);
  }
  std::sort(faces.begin(), faces.end());
  std::vector<double> out;
  for (const auto& f : faces)
    for (const auto& p : f) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace

template <class M>
bool cuts_fit(const dist::Communicator& comm, const SlabMesh<M>& slab) {
  std::vector<int> peers;
  std::vector<std::vector<double>> faces;
  if (slab.below) {
    peers.push_back(comm.rank() - 1);
    faces.push_back(faces_on(slab, CutSide::below));
  }
  if (slab.above) {
    peers.push_back(comm.rank() + 1);
    faces.push_back(faces_on(slab, CutSide::above));
  }
  std::vector<dist::Buffer> mine;
  for (const auto& f : faces) {
    mine.emplace_back();
    mine.back().put_vector(f);
  }
  std::vector<dist::Buffer> theirs = dist::exchange(comm, peers, mine);
  char fit = 1;
  for (std::size_t k = 0; k < peers.size(); ++k)
    fit = fit && theirs[k].get_vector<double>() == faces[k];
  const std::vector<char> all = dist::all_gather_values(comm, std::vector<char>{fit});
  return std::find(all.begin(), all.end(), 0) == all.end();
}

template <class M>
void resume_across_cuts(const dist::Communicator& comm, const SlabMesh<M>& slab, int rings,
                        const AdaptOptions& options) {
  AdaptOptions moves = options;
  moves.boundary.frozen = {};
  moves.progress = nullptr;
  const int rank = comm.rank();
  for (int parity = 0; parity < 2; ++parity) {
    // Cut j lies between ranks j and j + 1; this phase moves the cuts of its parity.
    const bool lower = slab.above && rank % 2 == parity;
    const bool upper = slab.below && (rank - 1) % 2 == parity;
    if (!lower && !upper) continue;
    const int peer = lower ? rank + 1 : rank - 1;
    std::vector<dist::Buffer> mine;
    mine.push_back(half_band(slab, lower, rings));
    std::vector<dist::Buffer> theirs = dist::exchange(comm, {peer}, mine);
    std::array<dist::Buffer, 2> halves =
        lower ? std::array<dist::Buffer, 2>{std::move(mine.front()), std::move(theirs.front())}
              : std::array<dist::Buffer, 2>{std::move(theirs.front()), std::move(mine.front())};
    Band<M> band = joined<M>(std::move(halves), options.min_edge, options.boundary);
    move_in_unit_frame(band, moves);
    take_back(band, lower ? 0 : 1, slab.result, options.near_interface);
  }
  recount_cells(slab.result, options);
}

template bool cuts_fit<QuadMesh>(const dist::Communicator&, const SlabMesh<QuadMesh>&);
template bool cuts_fit<HexMesh>(const dist::Communicator&, const SlabMesh<HexMesh>&);
template void resume_across_cuts<QuadMesh>(const dist::Communicator&, const SlabMesh<QuadMesh>&,
                                           int, const AdaptOptions&);
template void resume_across_cuts<HexMesh>(const dist::Communicator&, const SlabMesh<HexMesh>&, int,
                                          const AdaptOptions&);

}  // namespace hexadapt::cli
