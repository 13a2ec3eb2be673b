#include "hexadapt/assign/correction.h"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "hexadapt/assign/configuration_store.h"
#include "hexadapt/assign/cost.h"
#include "hexadapt/assign/enumerate.h"
#include "hexadapt/assign/local_ball.h"
#include "hexadapt/assign/manifold.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt::assign {

namespace {

template <class M>
void validate(const M& mesh, const Fractions& fractions, const CellMaterials& labels,
              const CorrectionOptions& options) {
  if (options.keep < 1) throw OptionError("keep must be at least 1");
  if (options.max_materials < 1) throw OptionError("max-materials must be at least 1");
  if (options.max_leaves < 1) throw OptionError("max-leaves must be at least 1");
  if (fractions.n_cells() != mesh.n_cells())
    throw Error("fractions hold " + std::to_string(fractions.n_cells()) + " cells, the mesh has " +
                std::to_string(mesh.n_cells()));
  if (labels.size() != static_cast<std::size_t>(mesh.n_cells()))
    throw Error("the assignment holds " + std::to_string(labels.size()) + " cells, the mesh has " +
                std::to_string(mesh.n_cells()));
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (labels[c] < 0 || labels[c] >= fractions.n_materials())
      throw Error("cell " + std::to_string(c.value()) + " is assigned material " +
                  std::to_string(labels[c]) + ", outside the " +
                  std::to_string(fractions.n_materials()) + " materials");
}

/// Position order (x, y, z, then id): the priority of nodes within a round.
template <class M>
void sort_by_position(const M& mesh, std::vector<NodeId>& nodes) {
  std::sort(nodes.begin(), nodes.end(), [&](NodeId a, NodeId b) {
    const Vec3 pa = mesh.point(a), pb = mesh.point(b);
    for (int d = 0; d < 3; ++d)
      if (pa[d] != pb[d]) return pa[d] < pb[d];
    return a < b;
  });
}

/// The nodes of n's ball other than n that are manifold now, each with its own ball, to
/// tell whether a configuration of n's ball keeps them manifold ("spares" them).
template <class M>
class Neighbourhood {
 public:
  Neighbourhood(const M& mesh, const CellMaterials& labels, const LocalBall<M>& ball) {
    std::vector<NodeId> nodes;
    for (CellId c : ball.cells())
      for (NodeId v : mesh.cell_nodes(c))
        if (v != ball.node()) nodes.push_back(v);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (NodeId v : nodes) {
      Neighbour nb{LocalBall<M>(mesh, v), {}, {}};
      for (CellId c : nb.ball.cells()) {
        const auto& bc = ball.cells();
        const auto at = std::find(bc.begin(), bc.end(), c);
        nb.in_centre.push_back(at == bc.end() ? -1 : static_cast<int>(at - bc.begin()));
        nb.labels.push_back(labels[c]);
      }
      if (is_manifold(nb.ball, nb.labels)) neighbours_.push_back(std::move(nb));
    }
  }

  bool spared_by(const std::vector<int>& config) const {
    std::vector<int> local;
    for (const Neighbour& nb : neighbours_) {
      local = nb.labels;
      for (std::size_t i = 0; i < local.size(); ++i)
        if (nb.in_centre[i] >= 0) local[i] = config[static_cast<std::size_t>(nb.in_centre[i])];
      if (!is_manifold(nb.ball, local)) return false;
    }
    return true;
  }

 private:
  struct Neighbour {
    LocalBall<M> ball;
    std::vector<int> in_centre;  ///< per cell of ball: its index in the centre's ball, or -1
    std::vector<int> labels;     ///< current labels of ball's cells
  };
  std::vector<Neighbour> neighbours_;
};

/// What a node keeps between its visits.
struct NodeState {
  ConfigurationStore store;
  std::vector<int> materials;
};

/// The state of Algorithm 1 between rounds.
template <class M>
class Corrector {
 public:
  Corrector(const M& mesh, const Fractions& fractions, const CorrectionOptions& options,
            CorrectionResult& result)
      : mesh_(mesh),
        fractions_(fractions),
        options_(options),
        result_(result),
        volumes_(cell_volumes(mesh)),
        claimed_(static_cast<std::size_t>(mesh.n_cells()), -1) {}

  const IdVector<CellId, double>& volumes() const { return volumes_; }

  /// One round over `pending`; returns the nodes to test for the next one.
  std::vector<NodeId> round(std::vector<NodeId> pending) {
    const int r = ++result_.rounds;
    sort_by_position(mesh_, pending);
    std::vector<NodeId> selected, next;
    for (NodeId n : pending) (claim(n, r) ? selected : next).push_back(n);
    std::vector<const Configuration*> chosen = solve(selected);
    for (std::size_t i = 0; i < selected.size(); ++i) {
      if (!chosen[i]) {
        fail(selected[i]);
        return {};
      }
      apply(selected[i], *chosen[i], next);
    }
    return next;
  }

 private:
  bool claim(NodeId n, int r) {
    const auto cells = mesh_.node_cells(n);
    for (CellId c : cells)
      if (claimed_[c] == r) return false;
    for (CellId c : cells) claimed_[c] = r;
    return true;
  }

  NodeState& state(NodeId n) { return states_[static_cast<std::size_t>(slot_.at(n))]; }

  std::vector<const Configuration*> solve(const std::vector<NodeId>& nodes) {
    std::vector<char> fresh(nodes.size(), 0);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (slot_.emplace(nodes[i], static_cast<int>(states_.size())).second) {
        states_.push_back(NodeState{ConfigurationStore(options_.keep), {}});
        fresh[i] = 1;
      }
    std::vector<EnumerationStats> stats(nodes.size());
    std::vector<const Configuration*> chosen(nodes.size(), nullptr);
    parallel_for(static_cast<std::int64_t>(nodes.size()), [&](std::int64_t k) {
      const auto i = static_cast<std::size_t>(k);
      NodeState& s = state(nodes[i]);
      const LocalBall<M> ball(mesh_, nodes[i]);
      if (fresh[i]) {
        const LocalProblem p = local_problem(ball, fractions_, volumes_, options_.max_materials);
        s.materials = p.materials;
        stats[i] = enumerate_configurations(ball, p, options_.max_leaves, s.store);
      }
      chosen[i] = options_.spare_neighbours ? take_sparing(ball, s.store) : s.store.take_next();
    });
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      result_.leaves += stats[i].leaves;
      result_.truncated_enumerations += stats[i].truncated ? 1 : 0;
      result_.nodes_treated += fresh[i];
    }
    return chosen;
  }

  /// CellMaterials are only read during the parallel phase, so this is thread-count independent.
  const Configuration* take_sparing(const LocalBall<M>& ball, ConfigurationStore& store) const {
    const Neighbourhood<M> around(mesh_, result_.labels, ball);
    return store.take_preferring(
        [&](const Configuration& config) { return around.spared_by(config.labels); });
  }

  void apply(NodeId n, const Configuration& config, std::vector<NodeId>& touched) {
    ++result_.node_solves;
    result_.max_visits = std::max(result_.max_visits, state(n).store.used());
    const LocalBall<M> ball(mesh_, n);
    for (int i = 0; i < ball.n_cells(); ++i) {
      const CellId c = ball.cell(i);
      const int m = config.labels[static_cast<std::size_t>(i)];
      if (result_.labels[c] == m) continue;
      result_.labels[c] = m;
      for (NodeId v : mesh_.cell_nodes(c)) touched.push_back(v);
    }
  }

  void fail(NodeId n) {
    NodeState& s = state(n);
    result_.failure = CorrectionFailure{n, mesh_.point(n), s.materials, s.store.size()};
  }

  const M& mesh_;
  const Fractions& fractions_;
  const CorrectionOptions& options_;
  CorrectionResult& result_;
  IdVector<CellId, double> volumes_;
  IdVector<CellId, int> claimed_;  ///< last round that selected a ball holding the cell
  std::unordered_map<NodeId, int> slot_;
  std::vector<NodeState> states_;
};

}  // namespace

template <class M>
CorrectionResult correct_assignment(const M& mesh, const Fractions& fractions,
                                    CellMaterials initial, const CorrectionOptions& options) {
  validate(mesh, fractions, initial, options);
  Timer total, phase;
  CorrectionResult result;
  result.labels = initial;
  Corrector<M> corrector(mesh, fractions, options, result);
  std::vector<NodeId> pending = non_manifold_nodes(mesh, result.labels);
  result.non_manifold_initial = static_cast<index_t>(pending.size());
  result.times.emplace_back("scan", phase.seconds());
  phase.restart();
  while (!pending.empty() && !result.failure) {
    if (options.progress)
      options.progress("manifold correction",
                       1.0 - static_cast<double>(pending.size()) /
                                 std::max<double>(1.0, result.non_manifold_initial));
    pending = non_manifold_among(mesh, result.labels, corrector.round(std::move(pending)));
  }
  if (options.progress) options.progress("manifold correction", 1.0);
  result.solved = !result.failure;
  result.times.emplace_back("correct", phase.seconds());
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (result.labels[c] != initial[c]) ++result.cells_changed;
  result.cost_initial = assignment_cost(fractions, corrector.volumes(), initial);
  result.cost_final = assignment_cost(fractions, corrector.volumes(), result.labels);
  result.times.emplace_back("total", total.seconds());
  return result;
}

template CorrectionResult correct_assignment(const QuadMesh&, const Fractions&, CellMaterials,
                                             const CorrectionOptions&);
template CorrectionResult correct_assignment(const HexMesh&, const Fractions&, CellMaterials,
                                             const CorrectionOptions&);

}  // namespace hexadapt::assign
