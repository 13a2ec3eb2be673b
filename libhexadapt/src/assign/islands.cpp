#include "hexadapt/assign/islands.h"

#include <algorithm>
#include <map>
#include <unordered_map>
#include <vector>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

// The pieces of `labels` over every rank: cells joined across faces within one material, each
// piece named by its root, the lowest global id among its cells. A rank knows the root of
// the cells it owns and of the ghost cells across a face from them (-1 for the others).
struct Pieces {
  IdVector<CellId, std::int64_t> root;        ///< per held cell
  std::map<std::int64_t, std::int64_t> size;  ///< root -> cells
};

// Roots joined over the ranks: every set is named by its lowest member.
class Roots {
 public:
  std::int64_t find(std::int64_t k) {
    std::int64_t r = k;
    for (auto it = parent_.find(r); it != parent_.end(); it = parent_.find(r)) r = it->second;
    while (k != r) {  // every member on the way now points at the root
      auto it = parent_.find(k);
      k = it->second;
      it->second = r;
    }
    return r;
  }
  void join(std::int64_t a, std::int64_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::unordered_map<std::int64_t, std::int64_t> parent_;
};

template <class M>
Pieces global_pieces(const M& mesh, const CellMaterials& labels, const dist::Distribution& where) {
  const dist::Block& b = where.block;
  // The pieces within the owned cells, each keyed by its lowest cell (the first reached).
  IdVector<CellId, std::int64_t> key(static_cast<std::size_t>(mesh.n_cells()), -1);
  std::vector<std::int64_t> keys, sizes, border_cell, border_key, link_key, link_cell;
  for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
    const CellId start(s);
    if (key[start] >= 0) continue;
    key[start] = b.global(start);
    std::vector<CellId> piece{start};
    for (std::size_t k = 0; k < piece.size(); ++k)
      for (int lf = 0; lf < M::faces_per_cell; ++lf) {
        const CellId o = mesh.neighbour(piece[k], lf);
        if (o.valid() && b.owns(o) && key[o] < 0 && labels[o] == labels[start]) {
          key[o] = key[start];
          piece.push_back(o);
        }
      }
    keys.push_back(key[start]);
    sizes.push_back(static_cast<std::int64_t>(piece.size()));
  }
  // Owned cells beside another rank's: where pieces meet across the ranks.
  for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
    const CellId c(s);
    bool border = false;
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (!o.valid() || b.owns(o)) continue;
      border = true;
      if (labels[o] != labels[c]) continue;
      link_key.push_back(key[c]);
      link_cell.push_back(b.global(o));
    }
    if (border) {
      border_cell.push_back(b.global(c));
      border_key.push_back(key[c]);
    }
  }
  const auto all = [&](const std::vector<std::int64_t>& v) {
    return dist::all_gather_values(where.comm, v);
  };
  keys = all(keys);
  sizes = all(sizes);
  border_cell = all(border_cell);
  border_key = all(border_key);
  link_key = all(link_key);
  link_cell = all(link_cell);
  std::unordered_map<std::int64_t, std::int64_t> border;
  for (std::size_t i = 0; i < border_cell.size(); ++i) border[border_cell[i]] = border_key[i];
  Roots roots;
  for (std::size_t i = 0; i < link_key.size(); ++i)
    roots.join(link_key[i], border.at(link_cell[i]));
  Pieces p{IdVector<CellId, std::int64_t>(static_cast<std::size_t>(mesh.n_cells()), -1), {}};
  for (std::size_t i = 0; i < keys.size(); ++i) p.size[roots.find(keys[i])] += sizes[i];
  for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
    const CellId c(s);
    p.root[c] = roots.find(key[c]);
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (o.valid() && !b.owns(o)) p.root[o] = roots.find(border.at(b.global(o)));
    }
  }
  return p;
}

// Whether held cell c (owned, or a ghost across a face from an owned cell) is in a small piece.
bool in_small(CellId c, const Pieces& p, index_t min_cells) {
  return p.size.at(p.root[c]) < min_cells;
}

}  // namespace

template <class M>
IslandResult remove_islands(const M& mesh, const Fractions& fractions, CellMaterials& labels,
                            index_t min_cells, const dist::Distribution& where) {
  IslandResult r;
  if (min_cells <= 1) return r;
  const dist::Block& b = where.block;
  const int n = fractions.n_materials();
  for (bool changed = true; changed;) {
    changed = false;
    const Pieces p = global_pieces(mesh, labels, where);
    // Every cell of a small piece goes to every rank: its root, id, fractions, and the
    // materials around it that are not in small pieces.
    std::vector<std::int64_t> root, cell;
    std::vector<double> fr;
    std::vector<char> around;
    for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
      const CellId c(s);
      if (!in_small(c, p, min_cells)) continue;
      root.push_back(p.root[c]);
      cell.push_back(b.global(c));
      for (int m = 0; m < n; ++m) fr.push_back(fractions(c, m));
      std::vector<char> mine(static_cast<std::size_t>(n), 0);
      for (int lf = 0; lf < M::faces_per_cell; ++lf) {
        const CellId o = mesh.neighbour(c, lf);
        if (o.valid() && !in_small(o, p, min_cells)) mine[static_cast<std::size_t>(labels[o])] = 1;
      }
      around.insert(around.end(), mine.begin(), mine.end());
    }
    root = dist::all_gather_values(where.comm, root);
    cell = dist::all_gather_values(where.comm, cell);
    fr = dist::all_gather_values(where.comm, fr);
    around = dist::all_gather_values(where.comm, around);
    // Per small piece, its cells in increasing id: the materials around it, and the one of
    // them most present in it (sum of fractions in that order; ties to the lowest index).
    std::vector<std::size_t> order(cell.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return root[x] < root[y] || (root[x] == root[y] && cell[x] < cell[y]);
    });
    CellMaterials next = labels;
    for (std::size_t lo = 0; lo < order.size();) {
      std::size_t hi = lo;
      while (hi < order.size() && root[order[hi]] == root[order[lo]]) ++hi;
      int best = -1;
      double best_sum = -1;
      for (int m = 0; m < n; ++m) {
        const auto k = static_cast<std::size_t>(m);
        bool near = false;
        double sum = 0;
        for (std::size_t i = lo; i < hi; ++i) {
          near = near || around[order[i] * static_cast<std::size_t>(n) + k];
          sum += fr[order[i] * static_cast<std::size_t>(n) + k];
        }
        if (near && sum > best_sum) best = m, best_sum = sum;
      }
      if (best >= 0) {
        for (std::size_t i = lo; i < hi; ++i) {
          const CellId held = b.local_cell(cell[order[i]]);
          if (held.valid()) next[held] = best;
        }
        ++r.islands;
        r.cells += static_cast<index_t>(hi - lo);
        changed = true;
      }
      lo = hi;
    }
    labels = std::move(next);
  }
  r.left = count_small_pieces(mesh, labels, min_cells, where);
  return r;
}

template <class M>
index_t count_small_pieces(const M& mesh, const CellMaterials& labels, index_t min_cells,
                           const dist::Distribution& where) {
  index_t count = 0;
  for (const auto& [root, size] : global_pieces(mesh, labels, where).size)
    count += size < min_cells;
  return count;
}

template <class M>
IslandResult remove_islands(const M& mesh, const Fractions& fractions, CellMaterials& labels,
                            index_t min_cells) {
  return remove_islands(mesh, fractions, labels, min_cells, dist::Distribution::whole(mesh));
}

template <class M>
index_t count_small_pieces(const M& mesh, const CellMaterials& labels, index_t min_cells) {
  return count_small_pieces(mesh, labels, min_cells, dist::Distribution::whole(mesh));
}

template IslandResult remove_islands(const QuadMesh&, const Fractions&, CellMaterials&, index_t,
                                     const dist::Distribution&);
template IslandResult remove_islands(const QuadMesh&, const Fractions&, CellMaterials&, index_t);
template index_t count_small_pieces(const QuadMesh&, const CellMaterials&, index_t,
                                    const dist::Distribution&);
template index_t count_small_pieces(const QuadMesh&, const CellMaterials&, index_t);
template IslandResult remove_islands(const HexMesh&, const Fractions&, CellMaterials&, index_t,
                                     const dist::Distribution&);
template IslandResult remove_islands(const HexMesh&, const Fractions&, CellMaterials&, index_t);
template index_t count_small_pieces(const HexMesh&, const CellMaterials&, index_t,
                                    const dist::Distribution&);
template index_t count_small_pieces(const HexMesh&, const CellMaterials&, index_t);

}  // namespace hexadapt::assign
