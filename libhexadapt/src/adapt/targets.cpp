#include "hexadapt/adapt/targets.h"

#include <Eigen/Dense>
#include <algorithm>
#include <string>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {

template <class M>
void check_inputs(const M& mesh, const Fractions& fractions, const IdVector<CellId, int>& material,
                  const IdVector<NodeId, NodeConstraint>& boundary) {
  const auto n = static_cast<std::size_t>(mesh.n_cells());
  if (static_cast<std::size_t>(fractions.n_cells()) != n || material.size() != n)
    throw InputError("", "",
                     "the mesh has " + std::to_string(n) + " cells but " +
                         std::to_string(fractions.n_cells()) + " fraction rows and " +
                         std::to_string(material.size()) + " material values");
  if (boundary.size() != static_cast<std::size_t>(mesh.n_nodes()))
    throw InternalError("boundary constraints do not match the mesh's nodes");
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (material[c] < 0 || material[c] >= fractions.n_materials())
      throw InputError("", "cell " + std::to_string(c.value()),
                       "material " + std::to_string(material[c]) + " is not one of the " +
                           std::to_string(fractions.n_materials()) + " materials");
}

// Cells sharing at least one node with c, c excluded, increasing ids.
template <class M>
std::vector<CellId> node_neighbour_cells(const M& mesh, CellId c) {
  std::vector<CellId> out;
  for (NodeId n : mesh.cell_nodes(c))
    for (CellId o : mesh.node_cells(n))
      if (o != c) out.push_back(o);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Vec3 project_on_plane(const Vec3& p, const Vec3& x, const Vec3& n) {
  return p - (p - x).dot(n) * n;
}

// The node's interface directions: the principal directions of the sum of n n^T over its
// faces whose weight is a fair share of the strongest (one for a plain interface, two at a
// 2D triple point or along a 3D triple curve).
NodeConstraint interface_directions(const Eigen::Matrix3d& tensor, double share) {
  NodeConstraint out;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(tensor);
  const Eigen::Vector3d lambda = eig.eigenvalues();  // increasing
  for (int k = 2; k >= 0; --k)
    if (lambda(k) > share * lambda(2) && lambda(k) > 0) out.add(Vec3(eig.eigenvectors().col(k)));
  return out;
}

}  // namespace

template <class M>
std::vector<Vec3> fraction_gradients(const M& mesh, const Fractions& fractions, CellId c,
                                     double eps_factor) {
  const std::vector<CellId> around = node_neighbour_cells(mesh, c);
  const Vec3 xc = cell_centroid(mesh, c);
  std::vector<Vec3> d;
  d.reserve(around.size());
  double mean_d2 = 0;
  for (CellId o : around) {
    d.push_back(cell_centroid(mesh, o) - xc);
    if constexpr (M::dim == 2) d.back().z() = 0;
    mean_d2 += d.back().squaredNorm();
  }
  const int nm = fractions.n_materials();
  std::vector<Vec3> g(static_cast<std::size_t>(nm), Vec3::Zero());
  if (around.empty()) return g;
  const double eps = eps_factor * mean_d2 / static_cast<double>(around.size());
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(3, nm);
  for (std::size_t i = 0; i < around.size(); ++i) {
    const double w = 1.0 / (d[i].squaredNorm() + eps);
    a += w * d[i] * d[i].transpose();
    for (int m = 0; m < nm; ++m) b.col(m) += w * (fractions(around[i], m) - fractions(c, m)) * d[i];
  }
  // A direction with no spread (2D: z; a single layer of hexes) gets a zero component.
  const double reg = 1e-12 * std::max(a.trace(), 1e-300);
  a += reg * Eigen::Matrix3d::Identity();
  const Eigen::MatrixXd x = a.ldlt().solve(b);
  for (int m = 0; m < nm; ++m) g[static_cast<std::size_t>(m)] = x.col(m);
  return g;
}

template <class M>
Targets compute_targets(const M& mesh, const Fractions& fractions,
                        const IdVector<CellId, int>& material,
                        const IdVector<NodeId, NodeConstraint>& boundary,
                        const TargetOptions& options) {
  check_inputs(mesh, fractions, material, boundary);
  Targets out;
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (o.valid() && c < o && material[c] != material[o])
        out.faces.push_back({c, o, lf, Vec3::Zero(), Vec3::Zero()});
    }
  // Gradients of the cells next to an interface face, one slot per such cell.
  std::vector<CellId> cells;
  for (const auto& f : out.faces) {
    cells.push_back(f.c0);
    cells.push_back(f.c1);
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  IdVector<CellId, index_t> slot(static_cast<std::size_t>(mesh.n_cells()), -1);
  for (std::size_t i = 0; i < cells.size(); ++i) slot[cells[i]] = static_cast<index_t>(i);
  std::vector<std::vector<Vec3>> grad(cells.size());
  (void)mesh.node_cells(NodeId(0));  // build the adjacency before the threads share it
  for_each_item(cells.size(), [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    grad[k] = fraction_gradients(mesh, fractions, cells[k], options.eps_factor);
  });

  for_each_item(out.faces.size(), [&](std::int64_t i) {
    InterfaceFace& f = out.faces[static_cast<std::size_t>(i)];
    const int m0 = material[f.c0], m1 = material[f.c1];
    const double d =
        fractions(f.c1, m0) - fractions(f.c0, m0) - fractions(f.c1, m1) + fractions(f.c0, m1);
    double t = std::abs(d) < options.tiny_denominator
                   ? 0.5
                   : (fractions(f.c0, m1) - fractions(f.c0, m0)) / d;
    t = std::clamp(t, 0.0, 1.0);
    const Vec3 p0 = cell_centroid(mesh, f.c0), p1 = cell_centroid(mesh, f.c1);
    f.point = p0 + t * (p1 - p0);
    const auto& g0 = grad[static_cast<std::size_t>(slot[f.c0])];
    const auto& g1 = grad[static_cast<std::size_t>(slot[f.c1])];
    const auto u0 = static_cast<std::size_t>(m0), u1 = static_cast<std::size_t>(m1);
    const Vec3 n = (1 - t) * (g0[u0] - g0[u1]) + t * (g1[u0] - g1[u1]);
    // Flat fractions give no gradient: fall back on the direction across the face.
    f.normal = n.norm() > 1e-12 ? Vec3(n.normalized()) : Vec3((p1 - p0).normalized());
  });

  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  IdVector<NodeId, Vec3> sum(nn, Vec3::Zero());
  IdVector<NodeId, int> count(nn, 0);
  IdVector<NodeId, Eigen::Matrix3d> tensor(nn, Eigen::Matrix3d::Zero());
  for (const auto& f : out.faces)
    for (NodeId v : mesh.face_nodes(f.c0, f.lf)) {
      sum[v] += project_on_plane(mesh.point(v), f.point, f.normal);
      count[v] += 1;
      tensor[v] += f.normal * f.normal.transpose();
    }
  out.has.assign(nn, 0);
  out.position.resize(nn);
  out.interface.resize(nn);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    const Vec3 p = mesh.point(v);
    out.position[v] = p;
    if (count[v] == 0) continue;
    out.has[v] = 1;
    ++out.n_interface_nodes;
    out.position[v] = p + boundary[v].project(sum[v] / count[v] - p);
    out.interface[v] = interface_directions(tensor[v], options.normal_share);
  }
  return out;
}

IdVector<NodeId, NodeConstraint> sliding_constraints(
    const IdVector<NodeId, NodeConstraint>& boundary, const Targets& targets) {
  if (boundary.size() != targets.interface.size())
    throw InternalError("sliding constraints: boundary and targets differ in size");
  IdVector<NodeId, NodeConstraint> out = boundary;
  for (NodeId v : id_range<NodeId>(static_cast<index_t>(out.size())))
    out[v].add(targets.interface[v]);
  return out;
}

template <class M>
double target_distance(const M& mesh, const Targets& targets) {
  double s = 0;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (targets.has[v]) s += (mesh.point(v) - targets.position[v]).norm();
  return s;
}

#define HEXADAPT_INSTANTIATE(M)                                                                 \
  template std::vector<Vec3> fraction_gradients<M>(const M&, const Fractions&, CellId, double); \
  template Targets compute_targets<M>(const M&, const Fractions&, const IdVector<CellId, int>&, \
                                      const IdVector<NodeId, NodeConstraint>&,                  \
                                      const TargetOptions&);                                    \
  template double target_distance<M>(const M&, const Targets&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
