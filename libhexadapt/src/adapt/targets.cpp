#include "hexadapt/adapt/targets.h"

#include <Eigen/Dense>
#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/adapt/target_volume.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/plane_cut.h"

namespace hexadapt {

namespace {

template <class M>
void check_inputs(const M& mesh, const Fractions& fractions, const CellMaterials& material,
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

// Centre and unit normal of local face lf of c (2D: the edge's normal in the plane).
template <class M>
std::pair<Vec3, Vec3> face_plane(const M& mesh, CellId c, int lf) {
  const auto nodes = mesh.face_nodes(c, lf);
  Vec3 centre = Vec3::Zero();
  for (NodeId v : nodes) centre += mesh.point(v);
  centre /= static_cast<double>(nodes.size());
  Vec3 n;
  if constexpr (M::dim == 2) {
    const Vec3 e = mesh.point(nodes[1]) - mesh.point(nodes[0]);
    n = Vec3(e.y(), -e.x(), 0);
  } else {
    n = (mesh.point(nodes[2]) - mesh.point(nodes[0]))
            .cross(mesh.point(nodes[3]) - mesh.point(nodes[1]));
  }
  return {centre, n.normalized()};
}

template <class M>
bool shares_a_node(const M& mesh, CellId c, const std::vector<NodeId>& nodes) {
  for (NodeId v : mesh.cell_nodes(c))
    if (std::find(nodes.begin(), nodes.end(), v) != nodes.end()) return true;
  return false;
}

// A cell centre (or its mirror image) taking part in a gradient fit, with the cell whose
// fractions it carries.
struct Sample {
  Vec3 x;
  CellId cell;
};

// The fit's samples: the node neighbours of c, and for each boundary face of c the mirror
// images of c and of the samples touching that face (the ghost layer a symmetric boundary
// would have). Without them a boundary cell's one-sided neighbourhood tilts the gradient of
// fractions that do not vary along the boundary.
template <class M>
std::vector<Sample> gradient_samples(const M& mesh, CellId c) {
  std::vector<Sample> out{{cell_centroid(mesh, c), c}};
  for (CellId o : node_neighbour_cells(mesh, c)) out.push_back({cell_centroid(mesh, o), o});
  for (int lf = 0; lf < M::faces_per_cell; ++lf) {
    if (mesh.neighbour(c, lf).valid()) continue;
    const auto fn = mesh.face_nodes(c, lf);
    const std::vector<NodeId> face(fn.begin(), fn.end());
    const auto [q, m] = face_plane(mesh, c, lf);
    const std::size_t n0 = out.size();
    for (std::size_t i = 0; i < n0; ++i)
      if (shares_a_node(mesh, out[i].cell, face))
        out.push_back({out[i].x - 2 * (out[i].x - q).dot(m) * m, out[i].cell});
  }
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

// Where, along the segment p0 p1 of the centres of the face's cells, the volume-consistent
// plane of normal f.normal crosses: in each mixed cell of the face the plane leaving the
// cell's share of m0 on the m0 side (f.normal points into m0); the mean over the mixed
// cells. nullopt when no plane could be bracketed or the plane is parallel to the segment.
template <class M>
std::optional<double> volume_crossing(const M& mesh, const Fractions& fractions,
                                      const InterfaceFace& f, int m0, const Vec3& p0,
                                      const Vec3& p1) {
  const double along = f.normal.dot(p1 - p0);
  if (std::abs(along) < 1e-9 * (p1 - p0).norm()) return std::nullopt;
  double sum = 0;
  int count = 0;
  for (CellId c : {f.c0, f.c1}) {
    const std::optional<double> s = plane_offset_for_share(mesh, c, f.normal, fractions(c, m0));
    if (!s) continue;
    sum += (*s - f.normal.dot(p0)) / along;
    ++count;
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

// The cell across the face of c opposite its local face lf: on a grid, the next cell along
// the axis that crosses lf. Invalid on the boundary.
template <class M>
CellId next_across(const M& mesh, CellId c, int lf) {
  return mesh.neighbour(c, M::dim == 2 ? (lf + 2) % 4 : lf ^ 1);
}

// Local face of c glued to o.
template <class M>
int face_towards(const M& mesh, CellId c, CellId o) {
  for (int lf = 0; lf < M::faces_per_cell; ++lf)
    if (mesh.neighbour(c, lf) == o) return lf;
  throw InternalError("face_towards: the cells are not neighbours");
}

// A sheet is a cell of material m whose two opposite faces along one axis both face other
// materials. Where face f's side s (the cell `sheet`, material m) is one, the mean of the two
// cells' planes thins it; instead the sheet gets the thickness of m's volume in the three
// cells of the column (other, sheet, beyond), placed at its centroid: m sits against the
// sheet in the two outer cells and in the sheet's middle. Returns where the sheet's side
// facing `other` crosses the centres' segment, in cell lengths from the sheet's centre, or
// nullopt when the cell is not a sheet along this axis.
template <class M>
std::optional<double> sheet_side(const M& mesh, const Fractions& fractions,
                                 const CellMaterials& material, CellId sheet, CellId other) {
  const int m = material[sheet];
  const CellId beyond = next_across(mesh, sheet, face_towards(mesh, sheet, other));
  if (!beyond.valid() || material[beyond] == m) return std::nullopt;
  const double fo = fractions(other, m), fs = fractions(sheet, m), fb = fractions(beyond, m);
  const double thickness = fo + fs + fb;
  if (thickness <= 0) return std::nullopt;
  const double centroid = (fo * (0.5 + fo / 2) - fb * (0.5 + fb / 2)) / thickness;
  return centroid + thickness / 2;
}

// The crossing on the segment p0 p1 (0 at c0, 1 at c1) where exactly one of the face's cells
// is a sheet along the segment's axis; nullopt otherwise.
template <class M>
std::optional<double> sheet_crossing(const M& mesh, const Fractions& fractions,
                                     const CellMaterials& material, const InterfaceFace& f) {
  const std::optional<double> s0 = sheet_side(mesh, fractions, material, f.c0, f.c1);
  const std::optional<double> s1 = sheet_side(mesh, fractions, material, f.c1, f.c0);
  if (s0.has_value() == s1.has_value()) return std::nullopt;
  return s0 ? *s0 : 1 - *s1;
}

}  // namespace

template <class M>
std::vector<Vec3> fraction_gradients(const M& mesh, const Fractions& fractions, CellId c,
                                     double eps_factor) {
  const std::vector<Sample> samples = gradient_samples(mesh, c);
  const Vec3 xc = samples.front().x;
  std::vector<Vec3> d;
  d.reserve(samples.size());
  double mean_d2 = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    d.push_back(samples[i].x - xc);
    if constexpr (M::dim == 2) d.back().z() = 0;
    mean_d2 += d.back().squaredNorm();
  }
  const int nm = fractions.n_materials();
  std::vector<Vec3> g(static_cast<std::size_t>(nm), Vec3::Zero());
  if (d.empty()) return g;
  const double eps = eps_factor * mean_d2 / static_cast<double>(d.size());
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(3, nm);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double w = 1.0 / (d[i].squaredNorm() + eps);
    const CellId o = samples[i + 1].cell;
    a += w * d[i] * d[i].transpose();
    for (int m = 0; m < nm; ++m) b.col(m) += w * (fractions(o, m) - fractions(c, m)) * d[i];
  }
  // A direction with no spread (2D: z; a single layer of hexes) gets a zero component.
  const double reg = 1e-12 * std::max(a.trace(), 1e-300);
  a += reg * Eigen::Matrix3d::Identity();
  const Eigen::MatrixXd x = a.ldlt().solve(b);
  for (int m = 0; m < nm; ++m) g[static_cast<std::size_t>(m)] = x.col(m);
  return g;
}

template <class M>
Targets compute_targets(const M& mesh, const Fractions& fractions, const CellMaterials& material,
                        const IdVector<NodeId, NodeConstraint>& boundary,
                        const TargetOptions& options, const VolumeParts* parts) {
  check_inputs(mesh, fractions, material, boundary);
  if (parts &&
      (parts->counted_cells.size() != static_cast<std::size_t>(mesh.n_cells()) ||
       parts->counted_nodes.size() != static_cast<std::size_t>(mesh.n_nodes()) || !parts->add_up))
    throw InternalError("compute_targets: the part's counted cells or nodes do not match it");
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

  const auto is_mixed = [&](CellId c, int m) { return fractions(c, m) > 0 && fractions(c, m) < 1; };
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
    const auto& g0 = grad[static_cast<std::size_t>(slot[f.c0])];
    const auto& g1 = grad[static_cast<std::size_t>(slot[f.c1])];
    const auto u0 = static_cast<std::size_t>(m0), u1 = static_cast<std::size_t>(m1);
    const Vec3 n = (1 - t) * (g0[u0] - g0[u1]) + t * (g1[u0] - g1[u1]);
    // Flat fractions give no gradient: fall back on the direction across the face (towards
    // m0, as the gradient of f_m0 - f_m1 points). The gradient is per unit length: the test
    // takes the change in fraction across the face, so that it holds in any unit.
    f.normal =
        n.norm() * (p1 - p0).norm() > 1e-12 ? Vec3(n.normalized()) : Vec3((p0 - p1).normalized());
    if (!is_mixed(f.c0, m0) && !is_mixed(f.c1, m0)) {
      // Both cells pure: the interface is the face itself.
      std::tie(f.point, f.normal) = face_plane(mesh, f.c0, f.lf);
      return;
    }
    std::optional<double> tv = sheet_crossing(mesh, fractions, material, f);
    if (!tv) tv = volume_crossing(mesh, fractions, f, m0, p0, p1);
    f.point = p0 + std::clamp(tv.value_or(t), 0.0, 1.0) * (p1 - p0);
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
  conserve_target_volumes(mesh, fractions, material, boundary, out, options, parts);
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

Vec3 surface_offset(const Vec3& p, const Vec3& target, const NodeConstraint& surface) {
  const Vec3 d = p - target;
  return d - surface.project(d);
}

double surface_distance(const Vec3& p, const Vec3& target, const NodeConstraint& surface) {
  return surface_offset(p, target, surface).norm();
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
                                      const TargetOptions&, const VolumeParts*);                \
  template double target_distance<M>(const M&, const Targets&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
