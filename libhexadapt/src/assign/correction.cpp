#include "hexadapt/assign/correction.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

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

/// A pending node as every rank sees it: its global id, place and the global ids of its cells.
struct Pending {
  std::int64_t node = 0;
  Vec3 point = Vec3::Zero();
  std::vector<std::int64_t> cells;
};

/// Position order (x, y, z, then id): the priority of nodes within a round.
bool before(const Pending& a, const Pending& b) {
  for (int d = 0; d < 3; ++d)
    if (a.point[d] != b.point[d]) return a.point[d] < b.point[d];
  return a.node < b.node;
}

/// A cell's new material, by global cell id.
struct Change {
  std::int64_t cell = 0;
  int material = 0;
};

/// What the rank owning a selected node found, for every rank to apply in the same order.
struct Outcome {
  std::int64_t order = 0;  ///< the node's place among the selected ones
  bool failed = false;
  bool fresh = false;  ///< first visit: its configurations were enumerated
  EnumerationStats stats;
  int visits = 0;  ///< configurations used after this visit
  std::vector<Change> changes;
  CorrectionFailure failure;  ///< when failed
};

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

/// The state of Algorithm 1 between rounds, on one rank's block.
template <class M>
class Corrector {
 public:
  Corrector(const M& mesh, const Fractions& fractions, const CorrectionOptions& options,
            const dist::Distribution& where, CorrectionResult& result)
      : mesh_(mesh),
        fractions_(fractions),
        options_(options),
        where_(where),
        result_(result),
        volumes_(cell_volumes(mesh, where.comm)) {}

  const IdVector<CellId, double>& volumes() const { return volumes_; }

  /// One round over the pending nodes this rank owns; returns the ones it owns to test for
  /// the next round.
  std::vector<NodeId> round(const std::vector<NodeId>& pending) {
    ++result_.rounds;
    const std::vector<Pending> all = gather_pending(pending);
    std::vector<std::int64_t> order;  // per selected node of this rank: its place
    std::vector<NodeId> selected, next;
    std::unordered_set<std::int64_t> claimed;
    std::int64_t n_selected = 0;
    for (const Pending& p : all) {
      const bool free = std::none_of(p.cells.begin(), p.cells.end(),
                                     [&](std::int64_t c) { return claimed.count(c) > 0; });
      if (free) claimed.insert(p.cells.begin(), p.cells.end());
      const NodeId n = where_.block.local_node(p.node);
      if (n.valid() && where_.block.owns(n)) {
        if (free) {
          selected.push_back(n);
          order.push_back(n_selected);
        } else {
          next.push_back(n);
        }
      }
      n_selected += free ? 1 : 0;
    }
    std::vector<Outcome> outcomes = gather_outcomes(solve(selected, order));
    apply(outcomes, next);
    return next;
  }

 private:
  /// Every rank's pending nodes, in position order.
  std::vector<Pending> gather_pending(const std::vector<NodeId>& pending) const {
    dist::Buffer mine;
    mine.put(static_cast<std::uint64_t>(pending.size()));
    for (NodeId n : pending) {
      mine.put(where_.block.global(n));
      mine.put_point(mesh_.point(n));
      std::vector<std::int64_t> cells;
      for (CellId c : mesh_.node_cells(n)) cells.push_back(where_.block.global(c));
      mine.put_vector(cells);
    }
    std::vector<Pending> all;
    for (dist::Buffer& b : dist::all_gather(where_.comm, mine)) {
      const auto n = b.get<std::uint64_t>();
      for (std::uint64_t i = 0; i < n; ++i) {
        Pending p;
        p.node = b.get<std::int64_t>();
        p.point = b.get_point();
        p.cells = b.get_vector<std::int64_t>();
        all.push_back(std::move(p));
      }
    }
    std::sort(all.begin(), all.end(), before);
    return all;
  }

  NodeState& state(NodeId n) { return states_[static_cast<std::size_t>(slot_.at(n))]; }

  /// Solves this rank's selected nodes (their balls are disjoint) from the labels at the
  /// start of the round.
  std::vector<Outcome> solve(const std::vector<NodeId>& nodes,
                             const std::vector<std::int64_t>& order) {
    std::vector<Outcome> out(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      out[i].order = order[i];
      if (slot_.emplace(nodes[i], static_cast<int>(states_.size())).second) {
        states_.push_back(NodeState{ConfigurationStore(options_.keep), {}});
        out[i].fresh = true;
      }
    }
    parallel_for(static_cast<std::int64_t>(nodes.size()), [&](std::int64_t k) {
      const auto i = static_cast<std::size_t>(k);
      NodeState& s = state(nodes[i]);
      const LocalBall<M> ball(mesh_, nodes[i]);
      if (out[i].fresh) {
        const LocalProblem p = local_problem(ball, fractions_, volumes_, options_.max_materials);
        s.materials = p.materials;
        out[i].stats = enumerate_configurations(ball, p, options_.max_leaves, s.store);
      }
      const Configuration* chosen =
          options_.spare_neighbours ? take_sparing(ball, s.store) : s.store.take_next();
      out[i].visits = s.store.used();
      if (!chosen) {
        out[i].failed = true;
        out[i].failure =
            CorrectionFailure{nodes[i], mesh_.point(nodes[i]), s.materials, s.store.size()};
        return;
      }
      for (int j = 0; j < ball.n_cells(); ++j) {
        const CellId c = ball.cell(j);
        const int m = chosen->labels[static_cast<std::size_t>(j)];
        if (result_.labels[c] != m) out[i].changes.push_back({where_.block.global(c), m});
      }
    });
    return out;
  }

  /// Every rank's outcomes, in the order of their nodes.
  std::vector<Outcome> gather_outcomes(const std::vector<Outcome>& mine) const {
    dist::Buffer b;
    b.put(static_cast<std::uint64_t>(mine.size()));
    for (const Outcome& o : mine) {
      b.put(o.order);
      b.put(o.failed);
      b.put(o.fresh);
      b.put(o.stats);
      b.put(o.visits);
      b.put_vector(o.changes);
      if (o.failed) {
        b.put(where_.block.global(o.failure.node));
        b.put_point(o.failure.position);
        b.put_vector(o.failure.materials);
        b.put(o.failure.stored);
      }
    }
    std::vector<Outcome> all;
    for (dist::Buffer& r : dist::all_gather(where_.comm, b)) {
      const auto n = r.get<std::uint64_t>();
      for (std::uint64_t i = 0; i < n; ++i) {
        Outcome o;
        o.order = r.get<std::int64_t>();
        o.failed = r.get<bool>();
        o.fresh = r.get<bool>();
        o.stats = r.get<EnumerationStats>();
        o.visits = r.get<int>();
        o.changes = r.get_vector<Change>();
        if (o.failed) {
          o.failure.node = NodeId(static_cast<index_t>(r.get<std::int64_t>()));
          o.failure.position = r.get_point();
          o.failure.materials = r.get_vector<int>();
          o.failure.stored = r.get<int>();
        }
        all.push_back(std::move(o));
      }
    }
    std::sort(all.begin(), all.end(),
              [](const Outcome& x, const Outcome& y) { return x.order < y.order; });
    return all;
  }

  /// CellMaterials are only read during the parallel phase, so this is thread-count independent.
  const Configuration* take_sparing(const LocalBall<M>& ball, ConfigurationStore& store) const {
    const Neighbourhood<M> around(mesh_, result_.labels, ball);
    return store.take_preferring(
        [&](const Configuration& config) { return around.spared_by(config.labels); });
  }

  /// Applies the outcomes in order up to the first failure (whose node is reported, with the
  /// global id), and adds the owned nodes of every changed cell to `touched`.
  void apply(const std::vector<Outcome>& outcomes, std::vector<NodeId>& touched) {
    for (const Outcome& o : outcomes) {
      result_.leaves += o.stats.leaves;
      result_.truncated_enumerations += o.stats.truncated ? 1 : 0;
      result_.nodes_treated += o.fresh ? 1 : 0;
    }
    for (const Outcome& o : outcomes) {
      if (o.failed) {
        result_.failure = o.failure;
        return;
      }
      ++result_.node_solves;
      result_.max_visits = std::max(result_.max_visits, o.visits);
      for (const Change& change : o.changes) {
        const CellId c = where_.block.local_cell(change.cell);
        if (!c.valid()) continue;
        result_.labels[c] = change.material;
        for (NodeId v : mesh_.cell_nodes(c))
          if (where_.block.owns(v)) touched.push_back(v);
      }
    }
  }

  const M& mesh_;
  const Fractions& fractions_;
  const CorrectionOptions& options_;
  const dist::Distribution& where_;
  CorrectionResult& result_;
  IdVector<CellId, double> volumes_;
  std::unordered_map<NodeId, int> slot_;
  std::vector<NodeState> states_;
};

}  // namespace

template <class M>
CorrectionResult correct_assignment(const M& mesh, const Fractions& fractions,
                                    CellMaterials initial, const CorrectionOptions& options,
                                    const dist::Distribution& where) {
  validate(mesh, fractions, initial, options);
  Timer total, phase;
  CorrectionResult result;
  result.labels = initial;
  Corrector<M> corrector(mesh, fractions, options, where, result);
  const auto owned = [&](std::vector<NodeId> nodes) {
    nodes.erase(
        std::remove_if(nodes.begin(), nodes.end(), [&](NodeId n) { return !where.block.owns(n); }),
        nodes.end());
    return nodes;
  };
  const auto everywhere = [&](const std::vector<NodeId>& nodes) {
    return dist::sum_in_rank_order(where.comm, static_cast<index_t>(nodes.size()));
  };
  std::vector<NodeId> pending = owned(non_manifold_nodes(mesh, result.labels));
  result.non_manifold_initial = everywhere(pending);
  result.times.emplace_back("scan", phase.seconds());
  phase.restart();
  for (index_t left = result.non_manifold_initial; left > 0 && !result.failure;
       left = everywhere(pending)) {
    if (options.progress)
      options.progress(
          "manifold correction",
          1.0 - static_cast<double>(left) / std::max<double>(1.0, result.non_manifold_initial));
    pending = non_manifold_among(mesh, result.labels, corrector.round(pending));
  }
  if (options.progress) options.progress("manifold correction", 1.0);
  result.solved = !result.failure;
  result.times.emplace_back("correct", phase.seconds());
  index_t changed = 0;
  ExactSum cost_initial, cost_final;
  for (index_t i = where.block.owned_cell_first; i < where.block.owned_cell_end; ++i) {
    const CellId c(i);
    changed += result.labels[c] != initial[c] ? 1 : 0;
    cost_initial.add(cell_cost(fractions, corrector.volumes(), c, initial[c]));
    cost_final.add(cell_cost(fractions, corrector.volumes(), c, result.labels[c]));
  }
  result.cells_changed = dist::sum_in_rank_order(where.comm, changed);
  result.cost_initial = dist::exact_sum(where.comm, cost_initial);
  result.cost_final = dist::exact_sum(where.comm, cost_final);
  result.times.emplace_back("total", total.seconds());
  return result;
}

template <class M>
CorrectionResult correct_assignment(const M& mesh, const Fractions& fractions,
                                    CellMaterials initial, const CorrectionOptions& options) {
  return correct_assignment(mesh, fractions, std::move(initial), options,
                            dist::Distribution::whole(mesh));
}

template CorrectionResult correct_assignment(const QuadMesh&, const Fractions&, CellMaterials,
                                             const CorrectionOptions&);
template CorrectionResult correct_assignment(const HexMesh&, const Fractions&, CellMaterials,
                                             const CorrectionOptions&);
template CorrectionResult correct_assignment(const QuadMesh&, const Fractions&, CellMaterials,
                                             const CorrectionOptions&, const dist::Distribution&);
template CorrectionResult correct_assignment(const HexMesh&, const Fractions&, CellMaterials,
                                             const CorrectionOptions&, const dist::Distribution&);

}  // namespace hexadapt::assign
