// The scores (size_criterion.h) of the cells around one node while the node tries positions,
// internal to the smoothing: the scores at the node's current position come from a mesh-wide
// cache of the cells none of whose nodes moved since they were scored, and a trial position
// scores the cells worst first, so that a trial that must not lower the local minimum is
// mostly refused at its first cell.
//
// The order changes no result: a trial that does not stop early is the minimum over all the
// cells, and one that stops is below its bound whatever the order (min_score_around).
#pragma once

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/core/span.h"

namespace hexadapt::detail {

/// Cell scores known for the current points; a cell's entry is valid until one of its nodes
/// moves. Nodes moved in parallel share no cell, so each cell is written by one thread.
struct CellScoreCache {
  IdVector<CellId, double> score;
  IdVector<CellId, char> known;
  explicit CellScoreCache(index_t n_cells)
      : score(static_cast<std::size_t>(n_cells), 0.0), known(static_cast<std::size_t>(n_cells), 0) {}
};

/// Smallest score of the cells around n at its current position (1 without cells), as
/// min_score_around, from the cache; the scores it lacked are computed and kept.
template <class M>
double cached_min_score(const M& mesh, NodeId n, const SizeCriterion& size,
                        CellScoreCache& cache) {
  double s = 1.0;
  for (CellId c : mesh.node_cells(n)) {
    if (!cache.known[c]) {
      cache.score[c] = cell_score(mesh, c, size);
      cache.known[c] = 1;
    }
    s = std::min(s, cache.score[c]);
  }
  return s;
}

template <class M>
class NodeScores {
 public:
  /// The scores of n's cells at its current position (cached or computed, and cached).
  NodeScores(const M& mesh, NodeId n, const SizeCriterion& size, CellScoreCache& cache)
      : mesh_(mesh), size_(size), node_(n) {
    const Span<CellId> cells = mesh.node_cells(n);
    cells_.reserve(cells.size());
    for (CellId c : cells) {
      if (!cache.known[c]) {
        cache.score[c] = cell_score(mesh, c, size);
        cache.known[c] = 1;
      }
      cells_.push_back({c, cache.score[c], 0.0});
    }
    sort_worst_first();
  }

  /// min_score_around at the node's position in the mesh now, the worst cells first.
  double trial(double stop_below = -std::numeric_limits<double>::infinity()) {
    double s = 1.0;
    for (Entry& e : cells_) {
      e.trial = cell_score(mesh_, e.cell, size_, stop_below);
      s = std::min(s, e.trial);
      if (s < stop_below) break;
    }
    return s;
  }

  /// Whether the last trial, which did not stop early, took a cell at or above `floor` below it.
  bool sinks_below(double floor) const {
    for (const Entry& e : cells_)
      if (e.current >= floor && e.trial < floor) return true;
    return false;
  }

  /// The last trial, which did not stop early, is the current position.
  void accept_trial() {
    for (Entry& e : cells_) e.current = e.trial;
    sort_worst_first();
  }

  /// Whether a cell scoring at most `at` now cannot score above it wherever the node goes
  /// (cell_score_bound): then no position raises the local minimum above `at`.
  bool capped(double at) const {
    for (const Entry& e : cells_) {
      if (e.current > at) break;  // worst first
      const auto& nodes = mesh_.cell_nodes(e.cell);
      const auto k = static_cast<std::size_t>(
          std::find(nodes.begin(), nodes.end(), node_) - nodes.begin());
      if (cell_score_bound(mesh_, e.cell, size_, k) <= at) return true;
    }
    return false;
  }

  /// Records the current scores in the cache (the node has left or kept its position).
  void store(CellScoreCache& cache) const {
    for (const Entry& e : cells_) cache.score[e.cell] = e.current;
  }

 private:
  struct Entry {
    CellId cell;
    double current;  ///< score at the node's current position
    double trial;    ///< score at the last trial position
  };

  // Insertion sort: a node has few cells, mostly in order already after a small move.
  void sort_worst_first() {
    for (std::size_t k = 1; k < cells_.size(); ++k)
      for (std::size_t j = k; j > 0 && cells_[j].current < cells_[j - 1].current; --j)
        std::swap(cells_[j], cells_[j - 1]);
  }

  const M& mesh_;
  const SizeCriterion& size_;
  NodeId node_;
  std::vector<Entry> cells_;  ///< lowest current score first
};

}  // namespace hexadapt::detail
