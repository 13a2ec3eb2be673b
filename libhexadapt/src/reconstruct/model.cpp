#include "hexadapt/reconstruct/model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "ref_cell.h"

namespace hexadapt::reconstruct {

using detail::ref_cell;
using detail::RefCell;

namespace {

// A lattice point identified by its integer weights on the coarse nodes, sorted by node.
using VertexKey = std::array<std::array<index_t, 2>, 8>;

struct KeyHash {
  std::size_t operator()(const VertexKey& k) const {
    std::size_t h = 1469598103934665603ull;
    for (const auto& e : k) {
      h = (h ^ static_cast<std::size_t>(e[0])) * 1099511628211ull;
      h = (h ^ static_cast<std::size_t>(e[1])) * 1099511628211ull;
    }
    return h;
  }
};

template <class M>
class Extractor {
 public:
  Extractor(const M& mesh, const PixelMesh& px, const CellMaterials& assignment)
      : mesh_(mesh), px_(px), assign_(assignment), rc_(ref_cell(M::dim)), n_(px.nsub()) {
    model_.dim = M::dim;
  }

  // Facets are found in parallel over fixed chunks of cells, then numbered in chunk order,
  // so the model does not depend on the thread count.
  InterfaceModel run() {
    constexpr index_t chunk = 2048;
    const index_t n_chunks = (mesh_.n_cells() + chunk - 1) / chunk;
    std::vector<std::vector<Facet>> found(static_cast<std::size_t>(n_chunks));
    parallel_for(n_chunks, [&](std::int64_t k) {
      auto& out = found[static_cast<std::size_t>(k)];
      const auto first = static_cast<index_t>(k * chunk);
      const index_t last = std::min(mesh_.n_cells(), first + chunk);
      for (index_t c = first; c < last; ++c) {
        if (px_.cell_block(CellId(c)) >= 0) inner_faces(CellId(c), out);
        for (int lf = 0; lf < M::faces_per_cell; ++lf) coarse_face(CellId(c), lf, out);
      }
    });
    for (auto& facets : found) {
      for (const Facet& f : facets) emit(f);
      std::vector<Facet>().swap(facets);
    }
    features();
    return std::move(model_);
  }

 private:
  // Face lf of pixel L of cell c, between materials la (inside) and lb.
  struct Facet {
    CellId c;
    std::array<int, 3> L;
    int lf, la, lb;
  };

  int label(CellId c, const std::array<int, 3>& L) const {
    const index_t b = px_.cell_block(c);
    return b >= 0 ? px_.label(px_.pixel_at(b, L)) : assign_[c];
  }

  void inner_faces(CellId c, std::vector<Facet>& out) const {
    for_lattice([&](const std::array<int, 3>& L) {
      for (int lf = 0; lf < rc_.n_faces; ++lf) {
        const auto a = static_cast<std::size_t>(rc_.face_axis[static_cast<std::size_t>(lf)]);
        if (!rc_.face_side[static_cast<std::size_t>(lf)] || L[a] == n_ - 1) continue;
        auto R = L;
        ++R[a];
        const int la = label(c, L), lb = label(c, R);
        if (la != lb) out.push_back({c, L, lf, la, lb});
      }
    });
  }

  void coarse_face(CellId c, int lf, std::vector<Facet>& out) const {
    const CellId o = mesh_.neighbour(c, lf);
    if (!o.valid() || o < c) return;
    if (px_.cell_block(c) < 0 && px_.cell_block(o) < 0 && assign_[c] == assign_[o]) return;
    const FaceLink fl = face_link(mesh_, c, lf);
    const auto a = static_cast<std::size_t>(rc_.face_axis[static_cast<std::size_t>(lf)]);
    const int layer = rc_.face_side[static_cast<std::size_t>(lf)] ? n_ - 1 : 0;
    for_lattice([&](const std::array<int, 3>& L) {
      if (L[a] != layer) return;
      std::array<int, 3> R{{0, 0, 0}};
      for (std::size_t t = 0; t < static_cast<std::size_t>(M::dim); ++t) {
        const int v = fl.axis[t] < 0 ? 0 : L[static_cast<std::size_t>(fl.axis[t])];
        R[t] = fl.flip[t] ? n_ - 1 - v : v;
      }
      const int la = label(c, L), lb = label(o, R);
      if (la != lb) out.push_back({c, L, lf, la, lb});
    });
  }

  template <class F>
  void for_lattice(F&& f) const {
    const int nk = M::dim == 3 ? n_ : 1;
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j < n_; ++j)
        for (int i = 0; i < n_; ++i) f(std::array<int, 3>{{i, j, k}});
  }

  void emit(const Facet& facet) {
    const CellId c = facet.c;
    const auto& L = facet.L;
    const int lf = facet.lf;
    int la = facet.la, lb = facet.lb;
    std::array<index_t, 4> f{{-1, -1, -1, -1}};
    const int npf = rc_.nodes_per_face;
    for (int i = 0; i < npf; ++i) {
      const auto v = static_cast<std::size_t>(
          rc_.face[static_cast<std::size_t>(lf)][static_cast<std::size_t>(i)]);
      f[static_cast<std::size_t>(i)] =
          vertex(c, {{L[0] + rc_.corner[v][0], L[1] + rc_.corner[v][1], L[2] + rc_.corner[v][2]}});
    }
    if (la > lb) {
      std::reverse(f.begin(), f.begin() + npf);
      std::swap(la, lb);
    }
    model_.facets.push_back(f);
    model_.facet_materials.push_back({{la, lb}});
  }

  index_t vertex(CellId c, const std::array<int, 3>& P) {
    VertexKey key;
    for (auto& e : key) e = {{-1, 0}};
    const auto nodes = mesh_.cell_nodes(c);
    std::size_t used = 0;
    for (std::size_t v = 0; v < static_cast<std::size_t>(rc_.n_corners); ++v) {
      index_t w = 1;
      for (std::size_t a = 0; a < static_cast<std::size_t>(M::dim); ++a)
        w *= rc_.corner[v][a] ? P[a] : n_ - P[a];
      if (w > 0) key[used++] = {{nodes[v].value(), w}};
    }
    // Insertion sort: at most 8 entries (std::sort trips GCC 12's -Warray-bounds here).
    for (std::size_t i = 1; i < used; ++i)
      for (std::size_t j = i; j > 0 && key[j] < key[j - 1]; --j) std::swap(key[j], key[j - 1]);
    const auto [it, inserted] = ids_.emplace(key, static_cast<index_t>(model_.points.size()));
    if (inserted) {
      double total = 1;
      for (int a = 0; a < M::dim; ++a) total *= n_;
      Vec3 x = Vec3::Zero();
      for (std::size_t i = 0; i < used; ++i)
        x += (key[i][1] / total) * mesh_.point(NodeId(key[i][0]));
      model_.points.push_back(x);
    }
    return it->second;
  }

  // Feature edges (3D) are facet edges not shared by exactly two facets or seen by three or
  // more materials; corners are where the feature graph does not just pass through.
  void features() {
    const int npf = model_.nodes_per_facet();
    std::vector<std::pair<std::array<index_t, 2>, std::size_t>> elements;
    for (std::size_t f = 0; f < model_.facets.size(); ++f) {
      const auto& q = model_.facets[f];
      if (M::dim == 2) {
        elements.push_back({{{q[0], q[0]}}, f});
        elements.push_back({{{q[1], q[1]}}, f});
      } else {
        for (int i = 0; i < npf; ++i) {
          index_t a = q[static_cast<std::size_t>(i)],
                  b = q[static_cast<std::size_t>((i + 1) % npf)];
          elements.push_back({{{std::min(a, b), std::max(a, b)}}, f});
        }
      }
    }
    std::sort(elements.begin(), elements.end());
    std::vector<int> degree(model_.points.size(), 0);
    for (std::size_t i = 0; i < elements.size();) {
      std::size_t j = i;
      std::vector<int> mats;
      while (j < elements.size() && elements[j].first == elements[i].first) {
        const auto& m = model_.facet_materials[elements[j].second];
        mats.push_back(m[0]);
        mats.push_back(m[1]);
        ++j;
      }
      std::sort(mats.begin(), mats.end());
      const auto n_mats = std::unique(mats.begin(), mats.end()) - mats.begin();
      if (j - i != 2 || n_mats >= 3) {
        const auto e = elements[i].first;
        if (M::dim == 2) {
          model_.corners.push_back(e[0]);
        } else {
          model_.curves.push_back(e);
          ++degree[static_cast<std::size_t>(e[0])];
          ++degree[static_cast<std::size_t>(e[1])];
        }
      }
      i = j;
    }
    if (M::dim == 3)
      for (std::size_t v = 0; v < degree.size(); ++v)
        if (degree[v] != 0 && degree[v] != 2) model_.corners.push_back(static_cast<index_t>(v));
  }

  const M& mesh_;
  const PixelMesh& px_;
  const CellMaterials& assign_;
  const RefCell& rc_;
  int n_;
  InterfaceModel model_;
  std::unordered_map<VertexKey, index_t, KeyHash> ids_;
};

// Flux of the position field through the bilinear patch q0 q1 q2 q3 (2x2 Gauss, exact).
double bilinear_flux(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& q3) {
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  double flux = 0;
  for (double u : g)
    for (double v : g) {
      const Vec3 x = (1 - u) * (1 - v) * q0 + u * (1 - v) * q1 + u * v * q2 + (1 - u) * v * q3;
      const Vec3 xu = (1 - v) * (q1 - q0) + v * (q2 - q3);
      const Vec3 xv = (1 - u) * (q3 - q0) + u * (q2 - q1);
      flux += 0.25 * x.dot(xu.cross(xv));
    }
  return flux;
}

}  // namespace

template <class M>
InterfaceModel extract_model(const M& mesh, const PixelMesh& pixels,
                             const CellMaterials& assignment) {
  return Extractor<M>(mesh, pixels, assignment).run();
}

double enclosed_volume(const InterfaceModel& model, int material) {
  double v = 0;
  for (std::size_t f = 0; f < model.facets.size(); ++f) {
    const auto& m = model.facet_materials[f];
    if (m[0] != material && m[1] != material) continue;
    const double sign = m[0] == material ? 1.0 : -1.0;
    const auto& q = model.facets[f];
    auto P = [&](std::size_t i) { return model.points[static_cast<std::size_t>(q[i])]; };
    if (model.dim == 2)
      v += sign * 0.5 * (P(0).x() * P(1).y() - P(1).x() * P(0).y());
    else
      v += sign * bilinear_flux(P(0), P(1), P(2), P(3)) / 3.0;
  }
  return v;
}

std::int64_t open_boundary_count(const InterfaceModel& model, int material) {
  // +1 for each directed element of the outward boundary, -1 for its reverse.
  std::map<std::array<index_t, 2>, std::int64_t> balance;
  const int npf = model.nodes_per_facet();
  for (std::size_t f = 0; f < model.facets.size(); ++f) {
    const auto& m = model.facet_materials[f];
    if (m[0] != material && m[1] != material) continue;
    const std::int64_t sign = m[0] == material ? 1 : -1;
    const auto& q = model.facets[f];
    if (model.dim == 2) {
      balance[{{q[0], q[0]}}] -= sign;  // a segment leaves its start and enters its end
      balance[{{q[1], q[1]}}] += sign;
      continue;
    }
    for (int i = 0; i < npf; ++i) {
      const index_t a = q[static_cast<std::size_t>(i)],
                    b = q[static_cast<std::size_t>((i + 1) % npf)];
      if (a < b)
        balance[{{a, b}}] += sign;
      else
        balance[{{b, a}}] -= sign;
    }
  }
  std::int64_t open = 0;
  for (const auto& [k, v] : balance) open += v < 0 ? -v : v;
  return open;
}

template InterfaceModel extract_model(const QuadMesh&, const PixelMesh&, const CellMaterials&);
template InterfaceModel extract_model(const HexMesh&, const PixelMesh&, const CellMaterials&);

}  // namespace hexadapt::reconstruct
