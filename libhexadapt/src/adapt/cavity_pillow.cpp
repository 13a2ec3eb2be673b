#include "hexadapt/adapt/cavity_pillow.h"

#include <algorithm>
#include <optional>
#include <string>

#include "cavity_patch.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {

using detail::CavityPatch;
using detail::EditableMesh;

// Cells of material m within vertex distance `range` of seed. `mark`: one zero per cell,
// left zero.
template <class M>
std::vector<CellId> cavity_cells(const EditableMesh<M>& mesh, const CellMaterials& material, int m,
                                 NodeId seed, int range, std::vector<char>& mark) {
  std::vector<CellId> out, front;
  for (CellId c : mesh.node_cells(seed))
    if (material[c] == m) front.push_back(c);
  for (int level = 1; level <= range && !front.empty(); ++level) {
    std::vector<CellId> next;
    for (CellId c : front) {
      if (mark[c.idx()]) continue;
      mark[c.idx()] = 1;
      out.push_back(c);
      if (level == range) continue;
      for (NodeId n : mesh.cell_nodes(c))
        for (CellId o : mesh.node_cells(n))
          if (material[o] == m && !mark[o.idx()]) next.push_back(o);
    }
    front = std::move(next);
  }
  for (CellId c : out) mark[c.idx()] = 0;
  std::sort(out.begin(), out.end());
  return out;
}

struct Seed {
  NodeId node;
  int range;
  std::vector<CellId> cells;  ///< the cavity, valid unless dirty
  bool dirty = true;
  bool alive = true;
};

// The seeds of one material, their cavities and which seeds hold each cell. A cavity is
// recomputed only when its seed's range changed or a publication touched a cell of it or
// next to it (the only cells whose nodes or node -> cells lists a publication changes).
class SeedSet {
 public:
  explicit SeedSet(std::vector<Seed> seeds) : seeds_(std::move(seeds)) {}
  Seed& operator[](std::size_t i) { return seeds_[i]; }
  /// The first live seed, or none.
  std::optional<std::size_t> first() const {
    for (std::size_t i = first_; i < seeds_.size(); ++i)
      if (seeds_[i].alive) return i;
    return std::nullopt;
  }
  template <class M>
  void refresh(const EditableMesh<M>& mesh, const CellMaterials& material, int m) {
    holders_.resize(static_cast<std::size_t>(mesh.n_cells()));
    mark_.resize(static_cast<std::size_t>(mesh.n_cells()), 0);
    for (std::size_t i = 0; i < seeds_.size(); ++i) {
      Seed& s = seeds_[i];
      if (!s.alive || !s.dirty) continue;
      forget(i);
      s.cells = cavity_cells(mesh, material, m, s.node, s.range, mark_);
      for (CellId c : s.cells) holders_[c.idx()].push_back(i);
      s.dirty = false;
    }
  }
  /// The live seeds whose cavities share cells with the first one's, transitively.
  std::vector<std::size_t> group(std::size_t first) const {
    std::vector<char> in(seeds_.size(), 0);
    std::vector<std::size_t> out{first}, stack{first};
    in[first] = 1;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      for (CellId c : seeds_[i].cells)
        for (std::size_t j : holders_[c.idx()])
          if (!in[j]) {
            in[j] = 1;
            out.push_back(j);
            stack.push_back(j);
          }
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  void drop(std::size_t i) {
    forget(i);
    seeds_[i].alive = false;
    while (first_ < seeds_.size() && !seeds_[first_].alive) ++first_;
  }
  /// Marks dirty every seed whose cavity holds one of `cells` (all when `all`).
  void touch(const std::vector<CellId>& cells, bool all) {
    if (all) {
      for (Seed& s : seeds_) s.dirty = true;
      return;
    }
    for (CellId c : cells)
      if (c.idx() < holders_.size())
        for (std::size_t j : holders_[c.idx()]) seeds_[j].dirty = true;
  }

 private:
  void forget(std::size_t i) {
    for (CellId c : seeds_[i].cells) {
      auto& h = holders_[c.idx()];
      h.erase(std::remove(h.begin(), h.end(), i), h.end());
    }
    seeds_[i].cells.clear();
  }
  std::vector<Seed> seeds_;
  std::vector<std::vector<std::size_t>> holders_;
  std::vector<char> mark_;
  std::size_t first_ = 0;
};

// True when a cell of the set has a frozen node.
template <class M>
bool touches_frozen(const EditableMesh<M>& mesh, const std::vector<CellId>& set,
                    const BoundaryOptions& boundary) {
  if (boundary.frozen.empty()) return false;
  for (CellId c : set)
    for (NodeId v : mesh.cell_nodes(c))
      if (boundary.is_frozen(v)) return true;
  return false;
}

// The patch of the set; the whole mesh when asked, or when the ring around the set cannot
// be a mesh of its own (a 2D ring pinched at a node).
template <class M>
CavityPatch<M> patch_of(const EditableMesh<M>& mesh, const std::vector<CellId>& set, bool whole) {
  if (!whole) {
    try {
      return mesh.patch(set, false);
    } catch (const MeshError&) {
    }
  }
  return mesh.patch(set, true);
}

// A pillowed patch, the size criterion on its cells, and the smallest score (quality/cell_score.h)
// among the cavity's and its layer's cells after smoothing.
template <class M>
struct TriedCavity {
  PillowResult<M> pillowed;
  SizeCriterion size;
  double worst = 1;
};

// Pillows the patch's set and smooths the nodes only the cavity and its layer use. `size`:
// the size criterion on the patch's cells.
template <class M>
TriedCavity<M> try_cavity(const CavityPatch<M>& patch, const SizeCriterion& size,
                          const StepSettings& o) {
  const M& mesh = patch.mesh;
  const IdVector<CellId, char>& set = patch.in_set;
  // The patch numbers its nodes its own way; the cavity touches no frozen node (cavity_pillow).
  const BoundaryOptions boundary = o.boundary.without_frozen();
  TriedCavity<M> t{
      pillow_cells(mesh, set, boundary_constraints(mesh, boundary), o.pillow, size), {}, 1};
  t.size = size.remapped(t.pillowed.cell_origin.raw());
  const M& pm = t.pillowed.mesh;
  auto in_cavity = [&](CellId c) { return c.value() >= mesh.n_cells() || set[c] != 0; };
  IdVector<NodeId, char> movable(static_cast<std::size_t>(pm.n_nodes()), 0);
  for (NodeId n : id_range<NodeId>(pm.n_nodes())) {
    const auto cells = pm.node_cells(n);
    movable[n] = !cells.empty() && std::all_of(cells.begin(), cells.end(), in_cavity);
  }
  smooth(t.pillowed.mesh, movable, boundary_constraints(pm, boundary), o.smooth, nullptr, t.size);
  for (CellId c : id_range<CellId>(pm.n_cells()))
    if (in_cavity(c)) t.worst = std::min(t.worst, cell_score(pm, c, t.size));
  return t;
}

// The global ids of the set's cells that end below the threshold or break the size criterion
// (all of them when the set could not be pillowed), increasing.
template <class M>
std::vector<CellId> bad_cells(const CavityPatch<M>& patch, const std::vector<CellId>& set,
                              const std::optional<TriedCavity<M>>& tried, double threshold) {
  if (!tried) return set;
  const PillowResult<M>& p = tried->pillowed;
  const auto n = static_cast<index_t>(patch.cells.size());
  std::vector<CellId> bad;
  for (CellId c : id_range<CellId>(p.mesh.n_cells()))
    if ((c.value() >= n || patch.in_set[c]) && cell_score(p.mesh, c, tried->size) < threshold)
      bad.push_back(patch.cells[p.cell_origin[c].idx()]);
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  return bad;
}

// The input cell each cell of the patch comes from.
inline std::vector<CellId> patch_origin(const std::vector<CellId>& origin,
                                        const std::vector<CellId>& patch_cells) {
  std::vector<CellId> out;
  out.reserve(patch_cells.size());
  for (CellId c : patch_cells) out.push_back(origin[c.idx()]);
  return out;
}

}  // namespace

template <class M>
CavityResult<M> cavity_pillow(const M& mesh, const CellMaterials& material, int n_materials,
                              const std::vector<NodeId>& seeds, const CavityOptions& options,
                              const StepSettings& shared, const SizeCriterion& size) {
  if (options.range < 1)
    throw OptionError("cavity range must be at least 1, got " + std::to_string(options.range));
  CavityResult<M> r;
  r.material = material;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) r.node_origin.push_back(v);
  for (CellId c : id_range<CellId>(mesh.n_cells())) r.cell_origin.push_back(c);
  EditableMesh<M> work(mesh);
  std::vector<NodeId> failed;
  for (int m = 0; m < n_materials; ++m) {
    std::vector<Seed> list;
    for (NodeId s : seeds)
      for (CellId c : work.node_cells(s))
        if (r.material[c] == m) {
          list.push_back({s, options.range, {}});
          break;
        }
    SeedSet pending(std::move(list));
    for (auto first = pending.first(); first; first = pending.first()) {
      pending.refresh(work, r.material, m);
      const std::vector<std::size_t> group = pending.group(*first);
      std::vector<CellId> set;
      CavityAttempt a;
      a.material = m;
      for (std::size_t i : group) {
        set.insert(set.end(), pending[i].cells.begin(), pending[i].cells.end());
        a.seeds.push_back(pending[i].node);
        a.range = std::max(a.range, pending[i].range);
      }
      std::sort(set.begin(), set.end());
      set.erase(std::unique(set.begin(), set.end()), set.end());
      a.cells = static_cast<index_t>(set.size());
      CavityPatch<M> patch = patch_of(work, set, options.whole_mesh);
      std::optional<TriedCavity<M>> tried;
      // A cavity around a frozen node would change faces that must stay the input's: it
      // fails, and its seeds shrink it.
      for (bool whole = options.whole_mesh; !touches_frozen(work, set, shared.boundary);
           whole = true) {
        try {
          tried.emplace(try_cavity(
              patch, size.remapped(patch_origin(r.cell_origin.raw(), patch.cells)), shared));
        } catch (const MeshError&) {
          // The set touches itself along an edge in a way its layer cannot follow (a face of
          // three cells): it cannot be published, and every seed in it shrinks. Confirmed in
          // the whole mesh, so that a kernel's refusal of the patch's own outline (a 2D ring
          // pinched at a node) never decides.
          if (!whole && patch.cells.size() < static_cast<std::size_t>(work.n_cells())) {
            patch = work.patch(set, true);
            continue;
          }
        }
        break;
      }
      a.min_quality = tried ? tried->worst : -1.0;
      a.published = tried && tried->worst >= shared.threshold && tried->pillowed.n_new_cells > 0;
      r.attempts.push_back(a);
      if (a.published) {
        const PillowResult<M>& p = tried->pillowed;
        const std::vector<NodeId> global = work.splice(patch, p);
        for (NodeId v : id_range<NodeId>(p.mesh.n_nodes()))
          if (v.idx() >= patch.nodes.size())
            r.node_origin.push_back(r.node_origin[global[p.node_origin[v].idx()]]);
        for (CellId c : id_range<CellId>(p.mesh.n_cells()))
          if (c.idx() >= patch.cells.size())
            r.cell_origin.push_back(r.cell_origin[patch.cells[p.cell_origin[c].idx()]]);
        for (index_t k = 0; k < p.n_new_cells; ++k) r.material.push_back(m);
        r.n_cells_added += p.n_new_cells;
        ++r.n_published;
        for (std::size_t i : group) pending.drop(i);
        pending.touch(patch.cells, options.whole_mesh);
        continue;
      }
      // The seeds whose cavity holds a cell below the threshold shrink it.
      const std::vector<CellId> bad = bad_cells(patch, set, tried, shared.threshold);
      bool any = false;
      for (std::size_t i : group) {
        Seed& s = pending[i];
        const bool blamed = std::any_of(s.cells.begin(), s.cells.end(), [&](CellId c) {
          return std::binary_search(bad.begin(), bad.end(), c);
        });
        if (!blamed) continue;
        any = true;
        s.dirty = true;
        if (--s.range < 1) pending.drop(i), failed.push_back(s.node);
      }
      if (!any)  // nothing to blame (an empty layer): give the group up
        for (std::size_t i : group) pending.drop(i), failed.push_back(pending[i].node);
    }
  }
  r.mesh = r.n_published > 0 ? work.build() : mesh;
  std::sort(failed.begin(), failed.end());
  failed.erase(std::unique(failed.begin(), failed.end()), failed.end());
  r.failed_seeds = std::move(failed);
  return r;
}

template CavityResult<QuadMesh> cavity_pillow<QuadMesh>(const QuadMesh&,
                                                        const IdVector<CellId, int>&, int,
                                                        const std::vector<NodeId>&,
                                                        const CavityOptions&, const StepSettings&,
                                                        const SizeCriterion&);
template CavityResult<HexMesh> cavity_pillow<HexMesh>(const HexMesh&, const IdVector<CellId, int>&,
                                                      int, const std::vector<NodeId>&,
                                                      const CavityOptions&, const StepSettings&,
                                                      const SizeCriterion&);

}  // namespace hexadapt
