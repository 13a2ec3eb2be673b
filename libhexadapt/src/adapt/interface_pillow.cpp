#include "hexadapt/adapt/interface_pillow.h"

#include <algorithm>
#include <optional>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/core/geometry.h"

namespace hexadapt {

namespace {

// The pillowed mesh of one attempt, the size criterion on its cells, and the ids (in the
// mesh before pillowing) of the cells the failing cells come from.
template <class M>
struct Attempt {
  PillowResult<M> p;
  SizeCriterion size;
  std::vector<CellId> failing_origins;
  index_t failing_cells = 0;
};

// Nodes the smoothing may move: the new ones and the free nodes of the cells around them.
template <class M>
IdVector<NodeId, char> layer_movable(const PillowResult<M>& p, index_t n_old,
                                     const IdVector<NodeId, char>& fixed) {
  const M& pm = p.mesh;
  IdVector<NodeId, char> movable(static_cast<std::size_t>(pm.n_nodes()), 0);
  for (NodeId v : id_range<NodeId>(pm.n_nodes())) {
    if (v.value() < n_old) continue;
    for (CellId c : pm.node_cells(v))
      for (NodeId o : pm.cell_nodes(c)) movable[o] = o.value() >= n_old || !fixed[o];
  }
  return movable;
}

template <class M>
bool touches(const M& mesh, CellId c, const IdVector<NodeId, char>& nodes) {
  for (NodeId v : mesh.cell_nodes(c))
    if (nodes[v]) return true;
  return false;
}

// With pillow_frozen: smooths the new copies of frozen nodes among themselves, every other
// node held, so that where they go depends on the cells around them only (and on where the
// layers pillowed before left the nodes of those cells).
template <class M>
void place_frozen_copies(PillowResult<M>& p, index_t n_old, const BoundaryOptions& pillowed,
                         const IdVector<NodeId, char>& movable, const StepSettings& o,
                         const SizeCriterion& size) {
  if (!pillowed.pillow_frozen || pillowed.frozen.empty()) return;
  IdVector<NodeId, char> copies(static_cast<std::size_t>(p.mesh.n_nodes()), 0);
  for (NodeId v : id_range<NodeId>(p.mesh.n_nodes()))
    copies[v] = v.value() >= n_old && movable[v] && pillowed.is_frozen(v);
  smooth(p.mesh, copies, boundary_constraints(p.mesh, pillowed.without_frozen()), o.smooth, nullptr,
         size);
}

// `origin`: the input node each node of mesh is.
template <class M>
Attempt<M> try_pillow(const M& mesh, const IdVector<CellId, char>& set,
                      const IdVector<NodeId, char>& fixed, const SizeCriterion& size,
                      const StepSettings& o, const IdVector<NodeId, NodeId>& origin) {
  // A frozen node's copies (pillow_frozen) start where a free node's would.
  Attempt<M> a{pillow_cells(mesh, set, boundary_constraints(mesh, o.boundary.without_frozen()),
                            o.pillow, size),
               {},
               {}};
  a.size = size.remapped(a.p.cell_origin.raw());
  const IdVector<NodeId, char> movable = layer_movable(a.p, mesh.n_nodes(), fixed);
  IdVector<NodeId, NodeId> input_node;
  for (NodeId v : a.p.node_origin) input_node.push_back(origin[v]);
  const BoundaryOptions pillowed = o.boundary.on_copies(input_node);
  place_frozen_copies(a.p, mesh.n_nodes(), pillowed, movable, o, a.size);
  smooth(a.p.mesh, movable, boundary_constraints(a.p.mesh, pillowed), o.smooth, nullptr, a.size);
  // Only the cells with a new or smoothed node changed: the others fail or pass as before
  // (a layer kept failing for another material is not this one's).
  for (CellId c : id_range<CellId>(a.p.mesh.n_cells()))
    if (touches(a.p.mesh, c, movable) && cell_score(a.p.mesh, c, a.size) < o.threshold) {
      a.failing_origins.push_back(a.p.cell_origin[c]);
      ++a.failing_cells;
    }
  std::sort(a.failing_origins.begin(), a.failing_origins.end());
  a.failing_origins.erase(std::unique(a.failing_origins.begin(), a.failing_origins.end()),
                          a.failing_origins.end());
  return a;
}

// Takes the cells around frozen nodes out of the set (their faces must stay the input's);
// returns how many were in it.
template <class M>
index_t leave_out_frozen(const M& mesh, const BoundaryOptions& boundary,
                         IdVector<CellId, char>& set) {
  if (boundary.frozen.empty()) return 0;
  index_t removed = 0;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    if (!set[c]) continue;
    const auto nodes = mesh.cell_nodes(c);
    if (std::none_of(nodes.begin(), nodes.end(), [&](NodeId v) { return boundary.is_frozen(v); }))
      continue;
    set[c] = 0;
    ++removed;
  }
  return removed;
}

// Takes out of the set the cells within vertex distance `range` of the failing origins
// (breadth first). Returns how many left.
template <class M>
index_t carve(const M& mesh, const std::vector<CellId>& origins, int range,
              IdVector<CellId, char>& set) {
  IdVector<CellId, int> level(static_cast<std::size_t>(mesh.n_cells()), -1);
  std::vector<index_t> queue;  // cell values: GCC 12 misreads a growing vector of ids here
  for (CellId c : origins) {
    level[c] = 0;
    queue.push_back(c.value());
  }
  index_t removed = 0;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const CellId c(queue[i]);
    removed += set[c] != 0;
    set[c] = 0;
    if (level[c] == range) continue;
    for (NodeId n : mesh.cell_nodes(c))
      for (CellId o : mesh.node_cells(n))
        if (level[o] < 0) {
          level[o] = level[c] + 1;
          queue.push_back(o.value());
        }
  }
  return removed;
}

// Whether a and b share a face (mesh.neighbour).
template <class M>
bool face_neighbours(const M& mesh, CellId a, CellId b) {
  for (int lf = 0; lf < M::faces_per_cell; ++lf)
    if (mesh.neighbour(a, lf) == b) return true;
  return false;
}

// In 3D, the set's cells around an edge that are not joined through faces around it: where
// the set touches itself along an edge only, which a layer cannot always follow (pillow.h).
// Increasing; none in 2D.
template <class M>
std::vector<CellId> edge_touching(const M& mesh, const IdVector<CellId, char>& set) {
  std::vector<CellId> out;
  if constexpr (M::dim == 3) {
    for (CellId c : id_range<CellId>(mesh.n_cells())) {
      if (!set[c]) continue;
      const auto nodes = mesh.cell_nodes(c);
      for (const auto& e : ref_hex::edges) {
        const NodeId a = nodes[static_cast<std::size_t>(e[0])];
        const NodeId b = nodes[static_cast<std::size_t>(e[1])];
        const auto at_b = mesh.node_cells(b);
        std::vector<CellId> around;  // the set's cells around the edge
        for (CellId o : mesh.node_cells(a))
          if (set[o] && std::find(at_b.begin(), at_b.end(), o) != at_b.end()) around.push_back(o);
        // What a walk from c across faces reaches among them (two cells around the edge that
        // share a face share one holding the edge).
        std::vector<CellId> reached{c};
        for (std::size_t k = 0; k < reached.size(); ++k)
          for (CellId o : around)
            if (std::find(reached.begin(), reached.end(), o) == reached.end() &&
                face_neighbours(mesh, reached[k], o))
              reached.push_back(o);
        if (reached.size() < around.size()) out.insert(out.end(), around.begin(), around.end());
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The local face across the cell from lf: binary hex order pairs faces 2a, 2a + 1 (ref_hex);
// a quad's edges go round, so edge lf faces edge lf + 2.
template <class M>
int facing_face(int lf) {
  if constexpr (M::dim == 3) return lf ^ 1;
  return (lf + 2) % 4;
}

// Cells of the mesh one cell thick between two other materials: across some pair of facing
// faces, both neighbours are of materials that differ from the cell's and from each other.
// A layer on both of its interfaces would put three cells across a sheet thinner than one,
// around the wedge where the three materials meet. Increasing.
template <class M>
std::vector<CellId> separating_sheets(const M& mesh, const CellMaterials& material) {
  std::vector<CellId> out;
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int lf = 0; lf < M::faces_per_cell / 2; ++lf) {
      const int first = M::dim == 3 ? 2 * lf : lf;
      const CellId a = mesh.neighbour(c, first), b = mesh.neighbour(c, facing_face<M>(first));
      if (a.valid() && b.valid() && material[a] != material[c] && material[b] != material[c] &&
          material[a] != material[b]) {
        out.push_back(c);
        break;
      }
    }
  return out;
}

}  // namespace

template <class M>
InterfacePillowResult<M> pillow_interfaces(const M& mesh, const CellMaterials& material,
                                           int n_materials, const IdVector<NodeId, char>& fixed,
                                           const SizeCriterion& size,
                                           const InterfacePillowOptions& options,
                                           const StepSettings& shared,
                                           const std::vector<CellId>& left_out_around) {
  if (options.rounds < 0 || options.carve < 0)
    throw OptionError("interface pillow rounds and carve must be >= 0");
  if (material.size() != static_cast<std::size_t>(mesh.n_cells()) ||
      fixed.size() != static_cast<std::size_t>(mesh.n_nodes()))
    throw InternalError("interface pillow: materials or fixed flags do not match the mesh");
  // r.mesh holds the last layer kept; the input stands for it until then (a copy of it would
  // be held beside the first layer's mesh).
  InterfacePillowResult<M> r{M(), material, {}, {}, 0, {}};
  bool any_kept = false;
  for (CellId c : id_range<CellId>(mesh.n_cells())) r.cell_origin.push_back(c);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) r.node_origin.push_back(v);
  IdVector<NodeId, char> still(fixed);
  SizeCriterion current = size.remapped(r.cell_origin.raw());
  const std::vector<CellId> sheets =
      options.sheet_layers ? std::vector<CellId>{} : separating_sheets(mesh, material);
  for (int m = 0; m < n_materials; ++m) {
    InterfacePillowAttempt log;
    log.material = m;
    const M& before = any_kept ? r.mesh : mesh;
    IdVector<CellId, char> set(static_cast<std::size_t>(before.n_cells()), 0);
    for (CellId c : id_range<CellId>(before.n_cells())) set[c] = r.material[c] == m;
    std::vector<CellId> around;  // the region's own cells: another's layer is not its own
    for (CellId c : left_out_around)
      if (material[c] == m) around.push_back(c);
    log.left_out = carve(mesh, around, options.carve, set);
    for (CellId c : sheets)
      if (material[c] == m && set[c]) {
        set[c] = 0;
        ++log.left_out;
        ++log.sheet_cells;
      }
    if (!shared.boundary.pillow_frozen)
      log.left_out += leave_out_frozen(before, shared.boundary, set);
    while (log.rounds < options.rounds && std::find(set.begin(), set.end(), 1) != set.end()) {
      ++log.rounds;
      std::optional<Attempt<M>> tried;
      try {
        tried.emplace(try_pillow(before, set, still, current, shared, r.node_origin));
      } catch (const MeshError&) {
        // The set touches itself along an edge where no layer can follow it: those places
        // are carved out, and the layer tried again.
        const index_t removed = carve(before, edge_touching(before, set), options.carve, set);
        if (removed == 0) break;
        log.left_out += removed;
        continue;
      }
      Attempt<M>& a = *tried;
      if (a.p.n_new_cells == 0) break;
      if (a.failing_origins.empty() || options.keep_failing) {
        log.kept = true;
        log.layer_cells = a.p.n_new_cells;
        log.failing = a.failing_cells;
        for (CellId c : id_range<CellId>(a.p.mesh.n_cells()))
          if (c.value() >= before.n_cells()) {
            r.cell_origin.push_back(r.cell_origin[a.p.cell_origin[c]]);
            r.material.push_back(m);
          }
        for (NodeId v : id_range<NodeId>(a.p.mesh.n_nodes()))
          if (v.value() >= before.n_nodes())
            r.node_origin.push_back(r.node_origin[a.p.node_origin[v]]);
        r.n_new_nodes += a.p.n_new_nodes;
        still.resize(static_cast<std::size_t>(a.p.mesh.n_nodes()), 0);
        current = std::move(a.size);
        r.mesh = std::move(a.p.mesh);
        any_kept = true;
        break;
      }
      const index_t removed = carve(before, a.failing_origins, options.carve, set);
      if (removed == 0) break;  // the failures are not the layer's: it cannot help
      log.left_out += removed;
    }
    r.attempts.push_back(log);
  }
  if (!any_kept) r.mesh = mesh;
  return r;
}

template InterfacePillowResult<QuadMesh> pillow_interfaces<QuadMesh>(
    const QuadMesh&, const IdVector<CellId, int>&, int, const IdVector<NodeId, char>&,
    const SizeCriterion&, const InterfacePillowOptions&, const StepSettings&,
    const std::vector<CellId>&);
template InterfacePillowResult<HexMesh> pillow_interfaces<HexMesh>(
    const HexMesh&, const IdVector<CellId, int>&, int, const IdVector<NodeId, char>&,
    const SizeCriterion&, const InterfacePillowOptions&, const StepSettings&,
    const std::vector<CellId>&);

}  // namespace hexadapt
