#include "hexadapt/adapt/cavity_pillow.h"

#include <algorithm>
#include <optional>
#include <map>
#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {

// Cells of material m within vertex distance `range` of seed.
template <class M>
std::vector<CellId> cavity_cells(const M& mesh, const IdVector<CellId, int>& material, int m,
                                 NodeId seed, int range) {
  std::vector<char> in(static_cast<std::size_t>(mesh.n_cells()), 0);
  std::vector<CellId> out, front;
  for (CellId c : mesh.node_cells(seed))
    if (material[c] == m) front.push_back(c);
  for (int level = 1; level <= range && !front.empty(); ++level) {
    std::vector<CellId> next;
    for (CellId c : front) {
      if (in[c.idx()]) continue;
      in[c.idx()] = 1;
      out.push_back(c);
      if (level == range) continue;
      for (NodeId n : mesh.cell_nodes(c))
        for (CellId o : mesh.node_cells(n))
          if (material[o] == m && !in[o.idx()]) next.push_back(o);
    }
    front = std::move(next);
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Seed {
  NodeId node;
  int range;
  std::vector<CellId> cells;
};

// The seeds whose cavities share cells with the first pending seed's, transitively.
std::vector<std::size_t> merged_group(const std::vector<Seed>& pending, index_t n_cells) {
  std::vector<char> in_group(pending.size(), 0), cell_in(static_cast<std::size_t>(n_cells), 0);
  in_group[0] = 1;
  for (CellId c : pending[0].cells) cell_in[c.idx()] = 1;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 1; i < pending.size(); ++i) {
      if (in_group[i]) continue;
      const bool overlaps = std::any_of(pending[i].cells.begin(), pending[i].cells.end(),
                                        [&](CellId c) { return cell_in[c.idx()] != 0; });
      if (!overlaps) continue;
      in_group[i] = 1;
      grew = true;
      for (CellId c : pending[i].cells) cell_in[c.idx()] = 1;
    }
  }
  std::vector<std::size_t> group;
  for (std::size_t i = 0; i < pending.size(); ++i)
    if (in_group[i]) group.push_back(i);
  return group;
}

// Pillows the set and smooths the nodes only the cavity and its layer use. Returns the
// pillowed mesh and the smallest quality among those cells.
template <class M>
std::pair<PillowResult<M>, double> try_cavity(const M& mesh, const IdVector<CellId, char>& set,
                                              const CavityOptions& o) {
  PillowResult<M> p = pillow_cells(mesh, set, boundary_constraints(mesh, o.boundary), o.pillow);
  const M& pm = p.mesh;
  auto in_cavity = [&](CellId c) { return c.value() >= mesh.n_cells() || set[c] != 0; };
  IdVector<NodeId, char> movable(static_cast<std::size_t>(pm.n_nodes()), 0);
  for (NodeId n : id_range<NodeId>(pm.n_nodes())) {
    const auto cells = pm.node_cells(n);
    movable[n] = !cells.empty() && std::all_of(cells.begin(), cells.end(), in_cavity);
  }
  smooth(p.mesh, movable, boundary_constraints(p.mesh, o.boundary), o.smooth);
  double worst = 1;
  for (CellId c : id_range<CellId>(pm.n_cells()))
    if (in_cavity(c)) worst = std::min(worst, pm.cell_quality(c));
  return {std::move(p), worst};
}

}  // namespace

template <class M>
CavityResult<M> cavity_pillow(const M& mesh, const IdVector<CellId, int>& material, int n_materials,
                              const std::vector<NodeId>& seeds, const CavityOptions& options) {
  if (options.range < 1)
    throw OptionError("cavity range must be at least 1, got " + std::to_string(options.range));
  CavityResult<M> r;
  r.mesh = mesh;
  r.material = material;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) r.node_origin.push_back(v);
  std::vector<NodeId> failed;
  for (int m = 0; m < n_materials; ++m) {
    std::vector<Seed> pending;
    for (NodeId s : seeds)
      for (CellId c : r.mesh.node_cells(s))
        if (r.material[c] == m) {
          pending.push_back({s, options.range, {}});
          break;
        }
    while (!pending.empty()) {
      for (Seed& s : pending) s.cells = cavity_cells(r.mesh, r.material, m, s.node, s.range);
      const std::vector<std::size_t> group = merged_group(pending, r.mesh.n_cells());
      IdVector<CellId, char> set(static_cast<std::size_t>(r.mesh.n_cells()), 0);
      CavityAttempt a;
      a.material = m;
      for (std::size_t i : group) {
        for (CellId c : pending[i].cells) set[c] = 1;
        a.seeds.push_back(pending[i].node);
        a.range = std::max(a.range, pending[i].range);
      }
      for (char x : set) a.cells += x != 0;
      std::optional<std::pair<PillowResult<M>, double>> tried;
      try {
        tried.emplace(try_cavity(r.mesh, set, options));
      } catch (const MeshError&) {
        // The set touches itself along an edge, so its layer would give a face three cells:
        // it cannot be published, and every seed in it shrinks as for a poor cavity.
      }
      a.min_quality = tried ? tried->second : -1.0;
      a.published = tried && tried->second >= options.threshold && tried->first.n_new_cells > 0;
      r.attempts.push_back(a);
      std::vector<char> drop(pending.size(), 0);
      if (a.published) {
        PillowResult<M>& p = tried->first;
        for (NodeId v : id_range<NodeId>(p.mesh.n_nodes()))
          if (v.value() >= r.mesh.n_nodes())
            r.node_origin.push_back(r.node_origin[p.node_origin[v]]);
        for (index_t k = 0; k < p.n_new_cells; ++k) r.material.push_back(m);
        r.n_cells_added += p.n_new_cells;
        ++r.n_published;
        r.mesh = std::move(p.mesh);
        for (std::size_t i : group) drop[i] = 1;
      } else {
        // The seeds whose cavity holds a cell below the threshold shrink it.
        std::vector<char> bad(static_cast<std::size_t>(r.mesh.n_cells()), 0);
        if (!tried) bad.assign(set.begin(), set.end());
        for (CellId c : id_range<CellId>(tried ? tried->first.mesh.n_cells() : 0)) {
          const PillowResult<M>& p = tried->first;
          const CellId origin = p.cell_origin[c];
          if ((c.value() >= r.mesh.n_cells() || set[c]) &&
              p.mesh.cell_quality(c) < options.threshold)
            bad[origin.idx()] = 1;
        }
        bool any = false;
        for (std::size_t i : group) {
          Seed& s = pending[i];
          const bool blamed = std::any_of(s.cells.begin(), s.cells.end(),
                                          [&](CellId c) { return bad[c.idx()] != 0; });
          if (!blamed) continue;
          any = true;
          if (--s.range < 1) drop[i] = 1, failed.push_back(s.node);
        }
        if (!any)  // nothing to blame (an empty layer): give the group up
          for (std::size_t i : group) drop[i] = 1, failed.push_back(pending[i].node);
      }
      std::vector<Seed> keep;
      for (std::size_t i = 0; i < pending.size(); ++i)
        if (!drop[i]) keep.push_back(std::move(pending[i]));
      pending = std::move(keep);
    }
  }
  std::sort(failed.begin(), failed.end());
  failed.erase(std::unique(failed.begin(), failed.end()), failed.end());
  r.failed_seeds = std::move(failed);
  return r;
}

template CavityResult<QuadMesh> cavity_pillow<QuadMesh>(const QuadMesh&,
                                                        const IdVector<CellId, int>&, int,
                                                        const std::vector<NodeId>&,
                                                        const CavityOptions&);
template CavityResult<HexMesh> cavity_pillow<HexMesh>(const HexMesh&, const IdVector<CellId, int>&,
                                                      int, const std::vector<NodeId>&,
                                                      const CavityOptions&);

}  // namespace hexadapt
