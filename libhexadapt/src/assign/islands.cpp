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

// What one rank knows of its pieces: the pieces within its owned cells, each keyed by its
// lowest cell (`key` per owned cell, `keys` and `sizes` per piece), its owned cells beside
// another rank's (`border_cell` with their key) and the ghost cells of the same material
// across a face from them (`link_cell`, with the key of the owned cell in `link_key`).
struct LocalPieces {
  IdVector<CellId, std::int64_t> key;
  std::vector<std::int64_t> keys, sizes, border_cell, border_key, link_key, link_cell;
};

template <class M>
LocalPieces local_pieces(const M& mesh, const CellMaterials& labels, const dist::Block& b) {
  LocalPieces l;
  l.key.assign(static_cast<std::size_t>(mesh.n_cells()), -1);
  for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
    const CellId start(s);
    if (l.key[start] >= 0) continue;
    l.key[start] = b.global(start);
    std::vector<CellId> piece{start};
    for (std::size_t k = 0; k < piece.size(); ++k)
      for (int lf = 0; lf < M::faces_per_cell; ++lf) {
        const CellId o = mesh.neighbour(piece[k], lf);
        if (o.valid() && b.owns(o) && l.key[o] < 0 && labels[o] == labels[start]) {
          l.key[o] = l.key[start];
          piece.push_back(o);
        }
      }
    l.keys.push_back(l.key[start]);
    l.sizes.push_back(static_cast<std::int64_t>(piece.size()));
  }
  for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
    const CellId c(s);
    bool border = false;
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (!o.valid() || b.owns(o)) continue;
      border = true;
      if (labels[o] != labels[c]) continue;
      l.link_key.push_back(l.key[c]);
      l.link_cell.push_back(b.global(o));
    }
    if (border) {
      l.border_cell.push_back(b.global(c));
      l.border_key.push_back(l.key[c]);
    }
  }
  return l;
}

template <class M>
Pieces global_pieces(const M& mesh, const CellMaterials& labels, const dist::Distribution& where) {
  const dist::Block& b = where.block;
  const LocalPieces l = local_pieces(mesh, labels, b);
  const auto all = [&](const std::vector<std::int64_t>& v) {
    return dist::all_gather_values(where.comm, v);
  };
  const std::vector<std::int64_t> keys = all(l.keys), sizes = all(l.sizes),
                                  border_cell = all(l.border_cell), border_key = all(l.border_key),
                                  link_key = all(l.link_key), link_cell = all(l.link_cell);
  std::unordered_map<std::int64_t, std::int64_t> border;
  for (std::size_t i = 0; i < border_cell.size(); ++i) border[border_cell[i]] = border_key[i];
  Roots roots;
  for (std::size_t i = 0; i < link_key.size(); ++i)
    roots.join(link_key[i], border.at(link_cell[i]));
  Pieces p{IdVector<CellId, std::int64_t>(static_cast<std::size_t>(mesh.n_cells()), -1), {}};
  for (std::size_t i = 0; i < keys.size(); ++i) p.size[roots.find(keys[i])] += sizes[i];
  for (index_t s = b.owned_cell_first; s < b.owned_cell_end; ++s) {
    const CellId c(s);
    p.root[c] = roots.find(l.key[c]);
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

// The cells of the small pieces of every rank: root, global id, fractions, and the materials
// around each that are not in small pieces (n_materials values per cell).
struct SmallCells {
  std::vector<std::int64_t> root, cell;
  std::vector<double> fractions;
  std::vector<char> around;
};

template <class M>
SmallCells small_cells(const M& mesh, const Fractions& f, const CellMaterials& labels,
                       const Pieces& p, index_t min_cells, const dist::Distribution& where) {
  const dist::Block& b = where.block;
  const auto n = static_cast<std::size_t>(f.n_materials());
  SmallCells s;
  for (index_t k = b.owned_cell_first; k < b.owned_cell_end; ++k) {
    const CellId c(k);
    if (!in_small(c, p, min_cells)) continue;
    s.root.push_back(p.root[c]);
    s.cell.push_back(b.global(c));
    for (std::size_t m = 0; m < n; ++m) s.fractions.push_back(f(c, static_cast<int>(m)));
    std::vector<char> around(n, 0);
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (o.valid() && !in_small(o, p, min_cells)) around[static_cast<std::size_t>(labels[o])] = 1;
    }
    s.around.insert(s.around.end(), around.begin(), around.end());
  }
  s.root = dist::all_gather_values(where.comm, s.root);
  s.cell = dist::all_gather_values(where.comm, s.cell);
  s.fractions = dist::all_gather_values(where.comm, s.fractions);
  s.around = dist::all_gather_values(where.comm, s.around);
  return s;
}

// The material a small piece (`cells`, indices into s, in increasing id) goes to: among those
// around it, the most present in its cells (sum of fractions in that order; ties to the
// lowest index); -1 when none is around.
int piece_material(const SmallCells& s, const std::vector<std::size_t>& cells, std::size_t n) {
  int best = -1;
  double best_sum = -1;
  for (std::size_t m = 0; m < n; ++m) {
    bool near = false;
    double sum = 0;
    for (std::size_t i : cells) {
      near = near || s.around[i * n + m];
      sum += s.fractions[i * n + m];
    }
    if (near && sum > best_sum) best = static_cast<int>(m), best_sum = sum;
  }
  return best;
}

// The pieces of s: per root, its cells' indices in increasing global id.
std::map<std::int64_t, std::vector<std::size_t>> by_piece(const SmallCells& s) {
  std::map<std::int64_t, std::vector<std::size_t>> out;
  for (std::size_t i = 0; i < s.cell.size(); ++i) out[s.root[i]].push_back(i);
  for (auto& [root, cells] : out)
    std::sort(cells.begin(), cells.end(),
              [&](std::size_t x, std::size_t y) { return s.cell[x] < s.cell[y]; });
  return out;
}

}  // namespace

template <class M>
IslandResult remove_islands(const M& mesh, const Fractions& fractions, CellMaterials& labels,
                            index_t min_cells, const dist::Distribution& where) {
  IslandResult r;
  if (min_cells <= 1) return r;
  for (bool changed = true; changed;) {
    changed = false;
    const SmallCells s =
        small_cells(mesh, fractions, labels, global_pieces(mesh, labels, where), min_cells, where);
    CellMaterials next = labels;
    for (const auto& [root, cells] : by_piece(s)) {
      const int m = piece_material(s, cells, static_cast<std::size_t>(fractions.n_materials()));
      if (m < 0) continue;
      for (std::size_t i : cells) {
        const CellId held = where.block.local_cell(s.cell[i]);
        if (held.valid()) next[held] = m;
      }
      ++r.islands;
      r.cells += static_cast<index_t>(cells.size());
      changed = true;
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
