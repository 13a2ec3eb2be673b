#include "hexadapt/reconstruct/mip.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <glpk.h>

#include "hexadapt/core/error.h"
#include "hexadapt/core/log.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/reconstruct/annealing.h"
#include "hexadapt/reconstruct/metrics.h"

namespace hexadapt::reconstruct {

std::string to_string(MipStatus s) {
  switch (s) {
    case MipStatus::optimal: return "optimal";
    case MipStatus::feasible: return "feasible";
    case MipStatus::timed_out_no_solution: return "timed_out_no_solution";
    case MipStatus::no_free_pixels: return "no_free_pixels";
  }
  return "?";
}

double mip_bytes_per_free_pixel(int n_materials, int dim) {
  return n_materials * (400.0 + 80.0 * (2 * dim + 2));
}

namespace {

// GLPK prints through this hook; whole lines go to our log at debug level.
int glpk_to_log(void* info, const char* s) {
  auto* line = static_cast<std::string*>(info);
  for (; *s; ++s) {
    if (*s == '\n') {
      log_debug("glpk: " + *line);
      line->clear();
    } else {
      *line += *s;
    }
  }
  return 1;  // nonzero: GLPK prints nothing itself
}

struct Term {
  int column;  // 1-based GLPK column, 0 for a constant
  double value;
};

// The programme: column numbers of c_{p,k}, the rows, and the |.| terms of the objective.
class Model {
 public:
  Model(const PixelMesh& px, const Fractions& f) : px_(px), f_(f), nm_(f.n_materials()) {
    prob_ = glp_create_prob();
    glp_set_obj_dir(prob_, GLP_MIN);
    for (std::int64_t p = 0; p < px.n_pixels(); ++p)
      if (px.pixel_free(p))
        for (int k = 0; k < nm_; ++k)
          if (f(cell(p), k) > 0) column_[{p, k}] = add_column(GLP_BV, 0);
    n_c_ = glp_get_num_cols(prob_);
  }
  ~Model() { glp_delete_prob(prob_); }
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  glp_prob* prob() { return prob_; }
  int n_c_columns() const { return n_c_; }
  double constant() const { return constant_; }

  void build() {
    for (std::int64_t p = 0; p < px_.n_pixels(); ++p) {
      if (!px_.pixel_free(p)) continue;
      std::vector<Term> one;
      for (int k = 0; k < nm_; ++k)
        if (int c = col(p, k)) one.push_back({c, 1.0});
      add_row(one, GLP_FX, 1.0);
      for (int k = 0; k < nm_; ++k) smoothness(p, k);
    }
    for (index_t b = 0; b < px_.n_blocks(); ++b) {
      if (!px_.block_free(b)) continue;
      const auto count = largest_remainder_counts(px_, f_, b);
      for (int k = 0; k < nm_; ++k) {
        if (f_(px_.block_cell(b), k) <= 0) continue;
        std::vector<Term> sum;
        for (std::int64_t p = px_.first_pixel(b); p < px_.first_pixel(b + 1); ++p)
          sum.push_back({col(p, k), 1.0});
        add_row(sum, GLP_FX, count[static_cast<std::size_t>(k)]);
      }
    }
    glp_load_matrix(prob_, static_cast<int>(ar_.size()) - 1, ia_.data(), ja_.data(), ar_.data());
  }

  /// Column values of the labels currently on the pixels (a feasible point).
  std::vector<double> point_of_labels() const {
    std::vector<double> x(static_cast<std::size_t>(glp_get_num_cols(prob_)) + 1, 0.0);
    for (const auto& [key, c] : column_)
      x[static_cast<std::size_t>(c)] = px_.label(key.first) == key.second ? 1.0 : 0.0;
    for (const auto& [t, terms] : abs_terms_) {
      double e = 0;
      for (const Term& term : terms) e += term.value * (term.column ? x[static_cast<std::size_t>(term.column)] : 1.0);
      x[static_cast<std::size_t>(t)] = std::abs(e);
    }
    return x;
  }

  void read_solution(PixelMesh& px) const {
    for (const auto& [key, c] : column_)
      if (glp_mip_col_val(prob_, c) > 0.5) px.set_label(key.first, key.second);
  }

 private:
  CellId cell(std::int64_t p) const { return px_.block_cell(px_.pixel_block(p)); }
  int col(std::int64_t p, int k) const {
    const auto it = column_.find({p, k});
    return it == column_.end() ? 0 : it->second;
  }
  int add_column(int kind, double cost) {
    const int c = glp_add_cols(prob_, 1);
    glp_set_col_kind(prob_, c, kind);
    if (kind == GLP_CV) glp_set_col_bnds(prob_, c, GLP_LO, 0.0, 0.0);
    glp_set_obj_coef(prob_, c, cost);
    return c;
  }
  void add_row(const std::vector<Term>& terms, int type, double rhs) {
    const int r = glp_add_rows(prob_, 1);
    glp_set_row_bnds(prob_, r, type, rhs, rhs);
    for (const Term& t : terms) {
      ia_.push_back(r);
      ja_.push_back(t.column);
      ar_.push_back(t.value);
    }
  }
  // t >= e and t >= -e with e = c_{p,k} - mean of the neighbours' c_{q,k}.
  void smoothness(std::int64_t p, int k) {
    std::vector<Term> e{{col(p, k), 1.0}};
    int n = 0;
    for (int lf = 0; lf < px_.faces_per_pixel(); ++lf) n += px_.neighbour(p, lf) >= 0 ? 1 : 0;
    double e0 = 0;
    for (int lf = 0; lf < px_.faces_per_pixel(); ++lf) {
      const std::int64_t q = px_.neighbour(p, lf);
      if (q < 0) continue;
      if (int c = px_.pixel_free(q) ? col(q, k) : 0)
        e.push_back({c, -1.0 / n});
      else if (!px_.pixel_free(q) && px_.label(q) == k)
        e0 -= 1.0 / n;
    }
    e.erase(std::remove_if(e.begin(), e.end(), [](const Term& t) { return t.column == 0; }),
            e.end());
    if (e.empty()) {
      constant_ += std::abs(e0);
      return;
    }
    const int t = add_column(GLP_CV, 1.0);
    std::vector<Term> plus{{t, 1.0}}, minus{{t, 1.0}};
    for (const Term& term : e) {
      plus.push_back({term.column, -term.value});
      minus.push_back({term.column, term.value});
    }
    add_row(plus, GLP_LO, e0);
    add_row(minus, GLP_LO, -e0);
    e.push_back({0, e0});
    abs_terms_.emplace_back(t, std::move(e));
  }

  const PixelMesh& px_;
  const Fractions& f_;
  int nm_;
  glp_prob* prob_ = nullptr;
  int n_c_ = 0;
  double constant_ = 0;
  std::map<std::pair<std::int64_t, int>, int> column_;
  std::vector<std::pair<int, std::vector<Term>>> abs_terms_;
  std::vector<int> ia_{0}, ja_{0};
  std::vector<double> ar_{0.0};
};

struct Search {
  std::vector<double> incumbent;  // handed to GLPK once
  bool given = false;
  double bound = -HUGE_VAL;
};

void callback(glp_tree* tree, void* info) {
  auto* s = static_cast<Search*>(info);
  if (glp_ios_reason(tree) == GLP_IHEUR && !s->given) {
    s->given = true;
    glp_ios_heur_sol(tree, s->incumbent.data());
  }
  if (const int node = glp_ios_best_node(tree)) s->bound = glp_ios_node_bound(tree, node);
}

int milliseconds(double seconds) {
  return static_cast<int>(std::min(2.0e9, std::max(1.0, seconds * 1000)));
}

}  // namespace

MipResult mip_assign(PixelMesh& pixels, const Fractions& fractions, const MipOptions& options) {
  if (!(options.time_limit > 0) || options.mip_gap < 0)
    throw OptionError("mip: the time limit must be > 0 and the gap >= 0");
  MipResult r;
  const Timer clock;
  largest_remainder_fill(pixels, fractions, options.seed);
  bool any_free = false;
  for (index_t b = 0; b < pixels.n_blocks() && !any_free; ++b) any_free = pixels.block_free(b);
  if (!any_free) return r;
  std::string line;
  glp_term_hook(glpk_to_log, &line);
  struct Unhook {
    ~Unhook() { glp_term_hook(nullptr, nullptr); }
  } unhook;
  Model model(pixels, fractions);
  model.build();
  r.n_variables = glp_get_num_cols(model.prob());
  r.n_constraints = glp_get_num_rows(model.prob());
  Search search{model.point_of_labels()};
  glp_smcp lp;
  glp_init_smcp(&lp);
  lp.tm_lim = milliseconds(options.time_limit);
  // The relaxation is highly degenerate: the presolver plus the dual simplex solve it in a
  // fraction of the primal simplex's time.
  lp.presolve = GLP_ON;
  lp.meth = GLP_DUALP;
  const int lp_ret = glp_simplex(model.prob(), &lp);
  r.status = MipStatus::timed_out_no_solution;
  if (lp_ret == 0 && glp_get_status(model.prob()) == GLP_OPT) {
    glp_iocp ip;
    glp_init_iocp(&ip);
    ip.tm_lim = milliseconds(options.time_limit - clock.seconds());
    ip.mip_gap = options.mip_gap;
    ip.cb_func = callback;
    ip.cb_info = &search;
    const int ret = glp_intopt(model.prob(), &ip);
    const int st = glp_mip_status(model.prob());
    if (st == GLP_OPT || st == GLP_FEAS) {
      model.read_solution(pixels);
      r.objective = glp_mip_obj_val(model.prob()) + model.constant();
      r.status = st == GLP_OPT && ret == 0 && options.mip_gap == 0 ? MipStatus::optimal
                                                                    : MipStatus::feasible;
      r.best_bound = r.status == MipStatus::optimal ? r.objective : search.bound + model.constant();
    } else if (ret != GLP_ETMLIM && ret != 0) {
      throw InternalError("GLPK failed on the sub-pixel programme (glp_intopt code " +
                          std::to_string(ret) + ")");
    }
  }
  if (r.status == MipStatus::timed_out_no_solution) {
    const auto x = model.point_of_labels();
    double obj = model.constant();
    for (int c = 1; c < static_cast<int>(x.size()); ++c)
      obj += glp_get_obj_coef(model.prob(), c) * x[static_cast<std::size_t>(c)];
    r.objective = obj;
  }
  r.seconds = clock.seconds();
  return r;
}

}  // namespace hexadapt::reconstruct
