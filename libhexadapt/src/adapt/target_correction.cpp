#include "hexadapt/adapt/target_correction.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hexadapt/adapt/model_projection.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

double surface_quad_quality(const std::array<Vec3, 4>& p) {
  const Vec3 area = (p[2] - p[0]).cross(p[3] - p[1]);
  double longest = 0;
  for (std::size_t i = 0; i < 4; ++i) longest = std::max(longest, (p[(i + 1) % 4] - p[i]).norm());
  const double an = area.norm();
  if (!(longest > 0) || !(an > 1e-26 * longest * longest)) return -1;
  const Vec3 n = area / an;
  double q = 1;
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3 next = p[(i + 1) % 4] - p[i], prev = p[(i + 3) % 4] - p[i];
    const double ln = next.norm(), lp = prev.norm();
    if (!(ln > 1e-13 * longest) || !(lp > 1e-13 * longest)) return -1;
    q = std::min(q, next.cross(prev).dot(n) / (ln * lp));
  }
  return q;
}

namespace {

enum class Role : char { none, surface, curve, fixed };

// The faces between cells of different materials with their pairs, the faces around each
// node, and each node's role and curve neighbours.
struct TargetSurface {
  std::vector<std::array<NodeId, 4>> faces;
  std::vector<std::array<int, 2>> pairs;
  IdVector<NodeId, std::vector<index_t>> node_faces;
  IdVector<NodeId, Role> role;
  IdVector<NodeId, std::vector<NodeId>> curve_next;  ///< ends of the node's feature edges
  double mean_edge = 0;                              ///< on the mesh points
};

void collect_faces(const HexMesh& mesh, const CellMaterials& material, TargetSurface& s) {
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    for (int lf = 0; lf < 6; ++lf) {
      const HalfFaceId h = HexMesh::half_face(c, lf);
      if (mesh.is_boundary(h)) continue;
      const CellId d = HexMesh::cell_of(mesh.opposite(h));
      if (d < c || material[c] == material[d]) continue;
      const auto f = mesh.face_nodes(c, lf);
      s.faces.push_back({f[0], f[1], f[2], f[3]});
      s.pairs.push_back({std::min(material[c], material[d]), std::max(material[c], material[d])});
    }
  s.node_faces.assign(static_cast<std::size_t>(mesh.n_nodes()), {});
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    for (NodeId v : s.faces[f]) s.node_faces[v].push_back(static_cast<index_t>(f));
}

// Feature edges: not two faces, or faces of different pairs.
void classify_nodes(const HexMesh& mesh, const IdVector<NodeId, NodeConstraint>& boundary,
                    TargetSurface& s) {
  std::vector<std::pair<std::array<index_t, 2>, index_t>> edges;
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    for (std::size_t i = 0; i < 4; ++i) {
      const index_t a = s.faces[f][i].value(), b = s.faces[f][(i + 1) % 4].value();
      edges.push_back({{std::min(a, b), std::max(a, b)}, static_cast<index_t>(f)});
    }
  std::sort(edges.begin(), edges.end());
  s.curve_next.assign(static_cast<std::size_t>(mesh.n_nodes()), {});
  double length = 0;
  std::size_t n_edges = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    bool mixed = false;
    while (j < edges.size() && edges[j].first == edges[i].first) {
      mixed |= s.pairs[static_cast<std::size_t>(edges[j].second)] !=
               s.pairs[static_cast<std::size_t>(edges[i].second)];
      ++j;
    }
    const NodeId a(edges[i].first[0]), b(edges[i].first[1]);
    length += (mesh.point(a) - mesh.point(b)).norm();
    ++n_edges;
    if (j - i != 2 || mixed) {
      s.curve_next[a].push_back(b);
      s.curve_next[b].push_back(a);
    }
    i = j;
  }
  s.mean_edge = n_edges ? length / static_cast<double>(n_edges) : 0;
  s.role.assign(static_cast<std::size_t>(mesh.n_nodes()), Role::none);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (s.node_faces[v].empty()) continue;
    const std::size_t features = s.curve_next[v].size();
    const int walls = boundary[v].n_normals();
    if (features == 0 && walls == 0)
      s.role[v] = Role::surface;
    else if (features == 2 && !boundary[v].fixed(3))
      s.role[v] = Role::curve;
    else
      s.role[v] = Role::fixed;
  }
}

std::array<Vec3, 4> face_points(const TargetSurface& s, const IdVector<NodeId, Vec3>& t,
                                std::size_t f) {
  const auto& q = s.faces[f];
  return {t[q[0]], t[q[1]], t[q[2]], t[q[3]]};
}

double min_face_quality(const TargetSurface& s, const IdVector<NodeId, Vec3>& t,
                        const std::vector<index_t>& faces) {
  double q = 1;
  for (index_t f : faces)
    q = std::min(q, surface_quad_quality(face_points(s, t, static_cast<std::size_t>(f))));
  return q;
}

// The material pair of a surface node: all its faces share it.
const std::array<int, 2>& node_pair(const TargetSurface& s, NodeId v) {
  return s.pairs[static_cast<std::size_t>(s.node_faces[v].front())];
}

// The node's position on the model near x, or nothing when the model is out of reach.
std::optional<Vec3> on_model(const TargetSurface& s, const ModelProjection& model,
                             const IdVector<NodeId, NodeConstraint>& boundary, NodeId v,
                             const Vec3& x, double radius) {
  if (s.role[v] == Role::surface) {
    const auto& p = node_pair(s, v);
    return model.on_surface(x, p[0], p[1], radius);
  }
  std::optional<Vec3> y = model.on_curve(x, radius);
  if (y) *y = x + boundary[v].project(*y - x);
  return y;
}

// Where smoothing sends the node: the area-weighted mean of its faces' centroids (surface)
// or the middle of its two curve neighbours (curve).
std::optional<Vec3> smoothed(const TargetSurface& s, const IdVector<NodeId, Vec3>& t, NodeId v) {
  if (s.role[v] == Role::curve) return 0.5 * (t[s.curve_next[v][0]] + t[s.curve_next[v][1]]);
  Vec3 sum = Vec3::Zero();
  double area = 0;
  for (index_t f : s.node_faces[v]) {
    const auto p = face_points(s, t, static_cast<std::size_t>(f));
    const double a = 0.5 * (p[2] - p[0]).cross(p[3] - p[1]).norm();
    sum += a * 0.25 * (p[0] + p[1] + p[2] + p[3]);
    area += a;
  }
  if (!(area > 0)) return std::nullopt;
  return sum / area;
}

double min_quality_all(const TargetSurface& s, const IdVector<NodeId, Vec3>& t, double poor,
                       index_t* n_poor) {
  double q = 1;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const double qf = surface_quad_quality(face_points(s, t, f));
    q = std::min(q, qf);
    *n_poor += qf < poor;
  }
  return q;
}

void check_inputs(const HexMesh& mesh, const CellMaterials& material,
                  const IdVector<NodeId, NodeConstraint>& boundary,
                  const reconstruct::InterfaceModel& model, const Targets& targets) {
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  if (material.size() != static_cast<std::size_t>(mesh.n_cells()) || boundary.size() != nn ||
      targets.position.size() != nn || targets.has.size() != nn)
    throw InputError("", "target correction", "sizes of the mesh, materials and targets differ");
  if (model.dim != 3) throw InputError("", "target correction", "the model is not 3D");
}

// The sweeps over the target surface, the targets as computed, and which nodes reached the
// model.
class Corrector {
 public:
  Corrector(TargetSurface& s, const reconstruct::InterfaceModel& model,
            const IdVector<NodeId, NodeConstraint>& boundary, Targets& targets,
            const TargetCorrectionOptions& o)
      : s_(s),
        boundary_(boundary),
        targets_(targets),
        t_(targets.position),
        o_(o),
        projection_(model, 0.5 * s.mean_edge),
        computed_(targets.position),
        on_(targets.position.size(), 0),
        radius_(o.search_radius * s.mean_edge),
        max_shift_(o.max_shift * s.mean_edge) {}

  // Every movable target onto the model; returns the nodes with no model in reach, which
  // become fixed.
  index_t project_all() {
    index_t missing = 0;
    for (NodeId v : id_range<NodeId>(static_cast<index_t>(t_.size()))) {
      if (!movable(v)) continue;
      const auto y = on_model(s_, projection_, boundary_, v, t_[v], radius_);
      if (!y) {
        s_.role[v] = Role::fixed;
        ++missing;
        continue;
      }
      // A refused node gets onto the model in the sweeps.
      const double before = min_face_quality(s_, t_, s_.node_faces[v]);
      try_move(v, *y, std::min(before, o_.min_projected_quality));
    }
    return missing;
  }

  // One Gauss-Seidel sweep of smoothing and projection; returns the nodes moved.
  index_t sweep() {
    index_t moved = 0;
    for (NodeId v : id_range<NodeId>(static_cast<index_t>(t_.size()))) {
      if (!movable(v)) continue;
      const auto goal = smoothed(s_, t_, v);
      if (!goal) continue;
      const Vec3 x = t_[v] + o_.relaxation * (*goal - t_[v]);
      const auto y = on_model(s_, projection_, boundary_, v, x, radius_);
      if (!y || (*y - t_[v]).norm() <= 1e-12 * s_.mean_edge) continue;
      const double shift = (*y - computed_[v]).norm();
      if (shift > max_shift_ && shift > (t_[v] - computed_[v]).norm()) continue;
      moved += try_move(v, *y, min_face_quality(s_, t_, s_.node_faces[v]));
    }
    return moved;
  }

  void statistics(TargetCorrectionResult& r) const {
    index_t n = 0;
    for (NodeId v : id_range<NodeId>(static_cast<index_t>(t_.size()))) {
      r.n_surface_nodes += s_.role[v] == Role::surface;
      r.n_curve_nodes += s_.role[v] == Role::curve;
      r.n_fixed_nodes += s_.role[v] == Role::fixed;
      r.n_off_model += movable(v) && !on_[v];
      if (!targets_.has[v]) continue;
      const double d = (t_[v] - computed_[v]).norm();
      r.mean_displacement += d;
      r.max_displacement = std::max(r.max_displacement, d);
      ++n;
    }
    if (n) r.mean_displacement /= static_cast<double>(n);
  }

 private:
  bool movable(NodeId v) const { return s_.role[v] == Role::surface || s_.role[v] == Role::curve; }

  // Moves v to y (a point of the model) unless one of its quads would fall below `floor`.
  bool try_move(NodeId v, const Vec3& y, double floor) {
    const Vec3 old = t_[v];
    t_[v] = y;
    if (min_face_quality(s_, t_, s_.node_faces[v]) < floor) {
      t_[v] = old;
      return false;
    }
    on_[v] = 1;
    return true;
  }

  TargetSurface& s_;
  const IdVector<NodeId, NodeConstraint>& boundary_;
  const Targets& targets_;
  IdVector<NodeId, Vec3>& t_;
  const TargetCorrectionOptions& o_;
  const ModelProjection projection_;
  const IdVector<NodeId, Vec3> computed_;
  IdVector<NodeId, char> on_;
  double radius_, max_shift_;
};

}  // namespace

void check_options(const TargetCorrectionOptions& o) {
  if (o.iterations < 0)
    throw OptionError("correction iterations must be >= 0, got " + std::to_string(o.iterations));
  if (!(o.relaxation > 0 && o.relaxation <= 1))
    throw OptionError("correction relaxation must be in (0, 1], got " +
                      std::to_string(o.relaxation));
  if (!(o.search_radius > 0 && std::isfinite(o.search_radius)))
    throw OptionError("correction search radius must be > 0, got " +
                      std::to_string(o.search_radius));
  if (!(o.min_projected_quality >= -1 && o.min_projected_quality <= 1))
    throw OptionError("correction min projected quality must be in [-1, 1], got " +
                      std::to_string(o.min_projected_quality));
  if (!(o.max_shift > 0))
    throw OptionError("correction max shift must be > 0, got " + std::to_string(o.max_shift));
}

TargetCorrectionResult correct_targets(const HexMesh& mesh, const CellMaterials& material,
                                       const IdVector<NodeId, NodeConstraint>& boundary,
                                       const reconstruct::InterfaceModel& model, Targets& targets,
                                       const TargetCorrectionOptions& o) {
  check_options(o);
  check_inputs(mesh, material, boundary, model, targets);
  TargetCorrectionResult r;
  TargetSurface s;
  collect_faces(mesh, material, s);
  r.n_faces = static_cast<index_t>(s.faces.size());
  if (s.faces.empty() || model.facets.empty()) {
    r.skipped = s.faces.empty() ? "no interface faces" : "the model has no facets";
    return r;
  }
  r.ran = true;
  classify_nodes(mesh, boundary, s);
  Corrector c(s, model, boundary, targets, o);
  r.min_quality_before = min_quality_all(s, targets.position, o.poor_below, &r.n_poor_before);
  r.n_unprojected = c.project_all();
  index_t ignored = 0;
  r.min_quality_projected = min_quality_all(s, targets.position, o.poor_below, &ignored);
  while (r.sweeps < o.iterations) {
    ++r.sweeps;
    if (c.sweep() == 0) break;
  }
  r.min_quality_after = min_quality_all(s, targets.position, o.poor_below, &r.n_poor_after);
  c.statistics(r);
  return r;
}

}  // namespace hexadapt
