#include "hexadapt/assign/enumerate.h"

#include <algorithm>
#include <numeric>

#include "hexadapt/assign/cost.h"
#include "hexadapt/assign/manifold.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

template <class M>
LocalProblem local_problem(const LocalBall<M>& ball, const Fractions& fractions,
                           const IdVector<CellId, double>& volumes, int max_materials) {
  LocalProblem p;
  std::vector<double> presence(static_cast<std::size_t>(fractions.n_materials()), 0.0);
  for (CellId c : ball.cells()) {
    p.volume += volumes[c];
    for (int m = 0; m < fractions.n_materials(); ++m)
      presence[static_cast<std::size_t>(m)] += fractions(c, m) * volumes[c];
  }
  std::vector<int> order;
  for (int m = 0; m < fractions.n_materials(); ++m) {
    bool any = false;
    for (CellId c : ball.cells()) any = any || fractions(c, m) > 0;
    if (any) order.push_back(m);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return presence[static_cast<std::size_t>(a)] > presence[static_cast<std::size_t>(b)];
  });
  if (static_cast<int>(order.size()) > max_materials)
    order.resize(static_cast<std::size_t>(max_materials));
  std::sort(order.begin(), order.end());
  p.materials = order;
  for (CellId c : ball.cells())
    for (int m : p.materials) p.cost.push_back(cell_cost(fractions, volumes, c, m));
  return p;
}

namespace {

/// Depth-first branch and bound over the ball's cells.
template <class M>
class Search {
 public:
  Search(const LocalBall<M>& ball, const LocalProblem& problem, std::int64_t max_leaves,
         ConfigurationStore& store)
      : ball_(ball), problem_(problem), max_leaves_(max_leaves), store_(store) {
    const auto k = static_cast<std::size_t>(ball.n_cells());
    const std::size_t p = problem.materials.size();
    order_.resize(k);
    lower_.assign(k + 1, 0.0);
    for (std::size_t i = k; i-- > 0;) {
      auto& o = order_[i];
      o.resize(p);
      std::iota(o.begin(), o.end(), 0);
      std::stable_sort(o.begin(), o.end(),
                       [&](std::size_t a, std::size_t b) { return cost(i, a) < cost(i, b); });
      lower_[i] = lower_[i + 1] + cost(i, o[0]);
    }
    labels_.assign(k, -1);
    tolerance_ = 1e-12 * problem.volume;
  }

  EnumerationStats run() {
    if (!problem_.materials.empty()) visit(0, 0.0);
    return stats_;
  }

 private:
  double cost(std::size_t cell, std::size_t j) const {
    return problem_.cost[cell * problem_.materials.size() + j];
  }

  void visit(std::size_t i, double partial) {
    if (stats_.truncated) return;
    // Equal costs found later lose to stored ones (arrival order), so >= prunes them too.
    if (store_.full() && partial + lower_[i] >= store_.worst_cost() - tolerance_) return;
    if (i == labels_.size()) {
      leaf(partial);
      return;
    }
    for (std::size_t j : order_[i]) {
      labels_[i] = problem_.materials[j];
      visit(i + 1, partial + cost(i, j));
    }
  }

  void leaf(double total) {
    if (++stats_.leaves > max_leaves_) {
      stats_.truncated = true;
      return;
    }
    if (!is_manifold(ball_, labels_)) return;
    ++stats_.manifold_leaves;
    store_.offer(total, labels_);
  }

  const LocalBall<M>& ball_;
  const LocalProblem& problem_;
  std::int64_t max_leaves_;
  ConfigurationStore& store_;
  std::vector<std::vector<std::size_t>> order_;  ///< per cell, candidates cheapest first
  std::vector<double> lower_;                    ///< cheapest completion from cell i on
  std::vector<int> labels_;
  double tolerance_ = 0;
  EnumerationStats stats_;
};

}  // namespace

template <class M>
EnumerationStats enumerate_configurations(const LocalBall<M>& ball, const LocalProblem& problem,
                                          std::int64_t max_leaves, ConfigurationStore& store) {
  return Search<M>(ball, problem, max_leaves, store).run();
}

#define HEXADAPT_INSTANTIATE(M)                                                                \
  template LocalProblem local_problem(const LocalBall<M>&, const Fractions&,                   \
                                      const IdVector<CellId, double>&, int);                   \
  template EnumerationStats enumerate_configurations(const LocalBall<M>&, const LocalProblem&, \
                                                     std::int64_t, ConfigurationStore&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt::assign
