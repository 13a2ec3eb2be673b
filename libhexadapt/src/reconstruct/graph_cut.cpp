#include "hexadapt/reconstruct/graph_cut.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

#include <maxflow.h>

#include "hexadapt/core/error.h"

namespace hexadapt::reconstruct {

namespace {

using Graph = maxflow::Graph<double, double, double>;
constexpr double inf = std::numeric_limits<double>::infinity();

[[noreturn]] void maxflow_error(const char* message) {
  throw InternalError(std::string("maxflow: ") + message);
}

// Geodesic distance (over adjacent pixel centres, in mean pixel widths) from every pixel to
// the nearest fixed pixel of `material`.
std::vector<double> distance_to_fixed(const PixelMesh& px, int material) {
  std::vector<double> d(static_cast<std::size_t>(px.n_pixels()), inf);
  using Item = std::pair<double, std::int64_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::int64_t p = 0; p < px.n_pixels(); ++p)
    if (!px.pixel_free(p) && px.label(p) == material) {
      d[static_cast<std::size_t>(p)] = 0;
      queue.push({0.0, p});
    }
  while (!queue.empty()) {
    const auto [dp, p] = queue.top();
    queue.pop();
    if (dp > d[static_cast<std::size_t>(p)]) continue;
    for (int lf = 0; lf < px.faces_per_pixel(); ++lf) {
      const std::int64_t q = px.neighbour(p, lf);
      if (q < 0) continue;
      const double dq = dp + (px.centre(p) - px.centre(q)).norm() / px.mean_width();
      if (dq < d[static_cast<std::size_t>(q)]) {
        d[static_cast<std::size_t>(q)] = dq;
        queue.push({dq, q});
      }
    }
  }
  return d;
}

class Expansion {
 public:
  Expansion(PixelMesh& px, const Fractions& f, const GraphCutOptions& o)
      : px_(px), o_(o), nm_(f.n_materials()) {
    for (std::int64_t p = 0; p < px.n_pixels(); ++p)
      if (px.pixel_free(p)) free_.push_back(p);
    data_.assign(free_.size() * static_cast<std::size_t>(nm_), inf);
    for (int m = 0; m < nm_; ++m) {
      const auto d = distance_to_fixed(px, m);
      double far = 0;
      for (double v : d)
        if (v < inf) far = std::max(far, v);
      for (std::size_t i = 0; i < free_.size(); ++i) {
        const double share = f(cell(free_[i]), m);
        if (share <= 0) continue;  // not allowed: stays infinite
        const double dist = d[static_cast<std::size_t>(free_[i])];
        data_[i * static_cast<std::size_t>(nm_) + static_cast<std::size_t>(m)] =
            (1 - share) * (dist < inf ? dist : far);
      }
    }
    node_.assign(static_cast<std::size_t>(px.n_pixels()), -1);
  }

  void initial_labels() {
    for (std::size_t i = 0; i < free_.size(); ++i) {
      const double* d = &data_[i * static_cast<std::size_t>(nm_)];
      px_.set_label(free_[i], static_cast<int>(std::min_element(d, d + nm_) - d));
    }
  }

  double energy() const {
    double e = 0;
    for (std::size_t i = 0; i < free_.size(); ++i) {
      e += o_.lambda * D(i, px_.label(free_[i]));
      for (int lf = 0; lf < px_.faces_per_pixel(); ++lf) {
        const std::int64_t q = px_.neighbour(free_[i], lf);
        // Pairs of two free pixels once, pairs with a fixed pixel once.
        if (q < 0 || (px_.pixel_free(q) && q < free_[i])) continue;
        if (px_.label(q) != px_.label(free_[i])) e += o_.beta;
      }
    }
    return e;
  }

  void expand(int alpha) {
    std::vector<std::size_t> vars;
    for (std::size_t i = 0; i < free_.size(); ++i) {
      node_[static_cast<std::size_t>(free_[i])] = -1;
      if (px_.label(free_[i]) != alpha && D(i, alpha) < inf) vars.push_back(i);
    }
    if (vars.empty()) return;
    Graph g(static_cast<int>(vars.size()), static_cast<int>(vars.size()) * px_.dim(), maxflow_error);
    g.add_node(static_cast<int>(vars.size()));
    for (std::size_t v = 0; v < vars.size(); ++v)
      node_[static_cast<std::size_t>(free_[vars[v]])] = static_cast<int>(v);
    std::vector<double> e0(vars.size()), e1(vars.size());
    for (std::size_t v = 0; v < vars.size(); ++v) {
      const std::int64_t p = free_[vars[v]];
      const int fp = px_.label(p);
      e0[v] += o_.lambda * D(vars[v], fp);
      e1[v] += o_.lambda * D(vars[v], alpha);
      for (int lf = 0; lf < px_.faces_per_pixel(); ++lf) {
        const std::int64_t q = px_.neighbour(p, lf);
        if (q < 0) continue;
        const int fq = px_.label(q);
        const int w = node_[static_cast<std::size_t>(q)];
        if (w < 0) {  // a constant neighbour
          e0[v] += o_.beta * (fp != fq);
          e1[v] += o_.beta * (alpha != fq);
          continue;
        }
        if (q < p) continue;
        // E(0,0)=A, E(0,1)=B, E(1,0)=C, E(1,1)=0 with x = 1 meaning "becomes alpha".
        const double A = o_.beta * (fp != fq), B = o_.beta * (fp != alpha), C = o_.beta * (alpha != fq);
        e1[v] += C - A;
        e1[static_cast<std::size_t>(w)] += -C;
        g.add_edge(static_cast<int>(v), w, B + C - A, 0);
      }
    }
    for (std::size_t v = 0; v < vars.size(); ++v)
      g.add_tweights(static_cast<int>(v), e1[v], e0[v]);
    g.maxflow();
    for (std::size_t v = 0; v < vars.size(); ++v)
      if (g.what_segment(static_cast<int>(v)) == Graph::SINK) px_.set_label(free_[vars[v]], alpha);
    for (std::size_t v = 0; v < vars.size(); ++v) node_[static_cast<std::size_t>(free_[vars[v]])] = -1;
  }

 private:
  CellId cell(std::int64_t p) const { return px_.block_cell(px_.pixel_block(p)); }
  double D(std::size_t i, int m) const {
    return data_[i * static_cast<std::size_t>(nm_) + static_cast<std::size_t>(m)];
  }

  PixelMesh& px_;
  const GraphCutOptions& o_;
  int nm_;
  std::vector<std::int64_t> free_;
  std::vector<double> data_;
  std::vector<int> node_;
};

}  // namespace

double graph_cut_bytes_per_free_pixel(int n_materials, int dim) {
  return 64.0 + 64.0 * dim + 8.0 * n_materials;
}

GraphCutResult graph_cut_assign(PixelMesh& pixels, const Fractions& fractions,
                                const GraphCutOptions& options) {
  if (!(options.lambda >= 0 && options.beta >= 0) || options.max_cycles < 1)
    throw OptionError("graph cut: lambda and beta must be >= 0 and cycles >= 1");
  Expansion ex(pixels, fractions, options);
  ex.initial_labels();
  GraphCutResult r;
  r.initial_energy = ex.energy();
  double e = r.initial_energy;
  for (r.cycles = 1; r.cycles <= options.max_cycles; ++r.cycles) {
    for (int alpha = 0; alpha < fractions.n_materials(); ++alpha) ex.expand(alpha);
    const double next = ex.energy();
    const bool gain = next < e - 1e-9 * std::max(1.0, std::abs(e));
    e = next;
    if (!gain) break;
  }
  r.cycles = std::min(r.cycles, options.max_cycles);
  r.final_energy = e;
  return r;
}

}  // namespace hexadapt::reconstruct
