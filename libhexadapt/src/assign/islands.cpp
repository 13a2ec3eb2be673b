#include "hexadapt/assign/islands.h"

#include <vector>

#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

// The pieces of `labels`: cells joined across faces within one material, numbered by their
// lowest cell, each piece's cells in increasing order of discovery.
template <class M>
std::vector<std::vector<CellId>> pieces(const M& mesh, const CellMaterials& labels) {
  IdVector<CellId, char> seen(static_cast<std::size_t>(mesh.n_cells()), 0);
  std::vector<std::vector<CellId>> out;
  for (CellId start : id_range<CellId>(mesh.n_cells())) {
    if (seen[start]) continue;
    seen[start] = 1;
    std::vector<CellId> piece{start};
    for (std::size_t k = 0; k < piece.size(); ++k)
      for (int lf = 0; lf < M::faces_per_cell; ++lf) {
        const CellId o = mesh.neighbour(piece[k], lf);
        if (o.valid() && !seen[o] && labels[o] == labels[start]) {
          seen[o] = 1;
          piece.push_back(o);
        }
      }
    out.push_back(std::move(piece));
  }
  return out;
}

// The material a small piece goes to: among those of its face neighbours outside small
// pieces, the most present in its cells; -1 when it has no such neighbour.
template <class M>
int new_material(const M& mesh, const Fractions& f, const CellMaterials& labels,
                 const IdVector<CellId, char>& in_small, const std::vector<CellId>& piece) {
  std::vector<char> around(static_cast<std::size_t>(f.n_materials()), 0);
  for (CellId c : piece)
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (o.valid() && !in_small[o]) around[static_cast<std::size_t>(labels[o])] = 1;
    }
  int best = -1;
  double best_sum = -1;
  for (int m = 0; m < f.n_materials(); ++m) {
    if (!around[static_cast<std::size_t>(m)]) continue;
    double sum = 0;
    for (CellId c : piece) sum += f(c, m);
    if (sum > best_sum) best = m, best_sum = sum;
  }
  return best;
}

}  // namespace

template <class M>
IslandResult remove_islands(const M& mesh, const Fractions& fractions, CellMaterials& labels,
                            index_t min_cells) {
  IslandResult r;
  if (min_cells <= 1) return r;
  for (bool changed = true; changed;) {
    changed = false;
    const auto all = pieces(mesh, labels);
    IdVector<CellId, char> in_small(static_cast<std::size_t>(mesh.n_cells()), 0);
    for (const auto& p : all)
      if (static_cast<index_t>(p.size()) < min_cells)
        for (CellId c : p) in_small[c] = 1;
    CellMaterials next = labels;
    for (const auto& p : all) {
      if (static_cast<index_t>(p.size()) >= min_cells) continue;
      const int m = new_material(mesh, fractions, labels, in_small, p);
      if (m < 0) continue;
      for (CellId c : p) next[c] = m;
      ++r.islands;
      r.cells += static_cast<index_t>(p.size());
      changed = true;
    }
    labels = std::move(next);
  }
  r.left = count_small_pieces(mesh, labels, min_cells);
  return r;
}

template <class M>
index_t count_small_pieces(const M& mesh, const CellMaterials& labels, index_t min_cells) {
  index_t n = 0;
  for (const auto& p : pieces(mesh, labels)) n += static_cast<index_t>(p.size()) < min_cells;
  return n;
}

template IslandResult remove_islands(const QuadMesh&, const Fractions&, CellMaterials&, index_t);
template IslandResult remove_islands(const HexMesh&, const Fractions&, CellMaterials&, index_t);
template index_t count_small_pieces(const QuadMesh&, const CellMaterials&, index_t);
template index_t count_small_pieces(const HexMesh&, const CellMaterials&, index_t);

}  // namespace hexadapt::assign
