#include "hexadapt/adapt/pillow.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

template <>
QuadMesh::CellNodes layer_cell<QuadMesh>(const QuadMesh::FaceNodes& f,
                                         const QuadMesh::FaceNodes& g) {
  // The set cell lies left of f0 -> f1 (counter-clockwise), the copies on that side.
  return {f[0], f[1], g[1], g[0]};
}

template <>
HexMesh::CellNodes layer_cell<HexMesh>(const HexMesh::FaceNodes& f, const HexMesh::FaceNodes& g) {
  // f's normal points away from the set cell: copies at the bottom (z-), originals on top,
  // in binary order (0, 1, 3, 2 counter-clockwise seen from above).
  return {g[0], g[1], g[3], g[2], f[0], f[1], f[3], f[2]};
}

namespace {

template <class M>
bool face_has_node(const M& mesh, CellId c, int lf, NodeId n) {
  for (NodeId v : mesh.face_nodes(c, lf))
    if (v == n) return true;
  return false;
}

// Labels the set's cells around n by face-connected fan (cells joined through a face that
// holds n); returns the label of each cell of `cells`, labels 0, 1, ... by first cell.
template <class M>
std::vector<int> fans_around(const M& mesh, NodeId n, const std::vector<CellId>& cells) {
  std::vector<int> label(cells.size(), -1);
  int next = 0;
  for (std::size_t s = 0; s < cells.size(); ++s) {
    if (label[s] >= 0) continue;
    label[s] = next;
    std::vector<std::size_t> stack{s};
    while (!stack.empty()) {
      const CellId c = cells[stack.back()];
      stack.pop_back();
      for (int lf = 0; lf < M::faces_per_cell; ++lf) {
        if (!face_has_node(mesh, c, lf, n)) continue;
        const auto it = std::find(cells.begin(), cells.end(), mesh.neighbour(c, lf));
        if (it == cells.end()) continue;
        const auto k = static_cast<std::size_t>(it - cells.begin());
        if (label[k] < 0) {
          label[k] = next;
          stack.push_back(k);
        }
      }
    }
    ++next;
  }
  return label;
}

// The set's cells around a split node, labelled by fan, and the inward normal of each fan's
// pillowed faces: the copy leaves its original across the interface, never along it.
struct Fans {
  std::vector<CellId> around;
  std::vector<int> fan;
  std::vector<Vec3> inward;
};

// The fans of the split nodes only, in node order, so that a grid with a thin interface pays
// a few bytes per node.
struct SplitFans {
  std::vector<NodeId> nodes;
  std::vector<Fans> of;  ///< of nodes[k]
};

template <class M>
SplitFans split_fans(const M& mesh, const IdVector<CellId, char>& in_set,
                     const IdVector<NodeId, char>& split,
                     const std::vector<std::pair<CellId, int>>& faces) {
  SplitFans out;
  IdVector<NodeId, index_t> place(split.size(), -1);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    if (!split[n]) continue;
    place[n] = static_cast<index_t>(out.nodes.size());
    out.nodes.push_back(n);
    Fans& f = out.of.emplace_back();
    for (CellId c : mesh.node_cells(n))
      if (in_set[c]) f.around.push_back(c);
    f.fan = fans_around(mesh, n, f.around);
    int n_fans = 0;
    for (int k : f.fan) n_fans = std::max(n_fans, k + 1);
    f.inward.assign(static_cast<std::size_t>(n_fans), Vec3::Zero());
  }
  for (const auto& [c, lf] : faces) {
    const Vec3 normal = face_normal(mesh, c, lf);
    for (NodeId v : mesh.face_nodes(c, lf)) {
      Fans& f = out.of[static_cast<std::size_t>(place[v])];
      const auto k = static_cast<std::size_t>(std::find(f.around.begin(), f.around.end(), c) -
                                              f.around.begin());
      f.inward[static_cast<std::size_t>(f.fan[k])] -= normal;
    }
  }
  return out;
}

// Where a copy goes, before scaling by the offset option: along the fan's inward normal
// (kept on the boundary), as far as the fan's cells' centres are from the node on average
// (not as deep as their mean centre: around a concave corner that lies at the node itself).
// Toward the mean centre when the normals cancel out.
Vec3 copy_offset(const NodeConstraint& boundary, const Vec3& inward, const Vec3& to_centre,
                 double reach) {
  const Vec3 d = boundary.project(inward);
  const double len = d.norm();
  if (len > 1e-9) return reach * d / len;
  return boundary.project(to_centre);
}

// The fraction of the way the copy goes: the offset option, raised so that the copy lies at
// least min_thickness x `floor` (the shortest edge its cells may have) from its original.
double copy_fraction(const PillowOptions& options, double reach, double floor) {
  const double wanted = options.min_thickness * floor;
  if (!(reach > 0) || options.offset * reach >= wanted) return options.offset;
  return std::min(wanted / reach, std::max(options.offset, options.max_offset));
}

}  // namespace

template <class M>
PillowResult<M> pillow_cells(const M& mesh, const IdVector<CellId, char>& in_set,
                             const IdVector<NodeId, NodeConstraint>& boundary,
                             const PillowOptions& options, const SizeCriterion& size) {
  if (in_set.size() != static_cast<std::size_t>(mesh.n_cells()) ||
      boundary.size() != static_cast<std::size_t>(mesh.n_nodes()))
    throw InternalError("pillow: cell set or constraints do not match the mesh");
  if (!(options.offset > 0 && options.offset < 1))
    throw OptionError("pillow offset must be in (0, 1), got " + std::to_string(options.offset));
  if (!(options.max_offset > 0 && options.max_offset < 1) || !(options.min_thickness >= 0))
    throw OptionError("pillow max_offset must be in (0, 1) and min_thickness >= 0");
  std::vector<std::pair<CellId, int>> faces;
  IdVector<NodeId, char> split(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    if (!in_set[c]) continue;
    for (int lf = 0; lf < M::faces_per_cell; ++lf) {
      const CellId o = mesh.neighbour(c, lf);
      if (!o.valid() || in_set[o]) continue;
      faces.emplace_back(c, lf);
      for (NodeId v : mesh.face_nodes(c, lf)) split[v] = 1;
    }
  }

  const SplitFans fans = split_fans(mesh, in_set, split, faces);
  std::size_t n_copies = 0;
  for (const Fans& f : fans.of) n_copies += f.inward.size();

  // Every array at its final size from the start: a grid-sized array grown by doubling
  // would hold up to three times its size while it grows.
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  const auto nc = static_cast<std::size_t>(mesh.n_cells());
  std::vector<Vec3> points;
  points.reserve(nn + n_copies);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) points.push_back(mesh.point(v));
  std::vector<typename M::CellNodes> cells;
  cells.reserve(nc + faces.size());
  for (CellId c : id_range<CellId>(mesh.n_cells())) cells.push_back(mesh.cell_nodes(c));
  PillowResult<M> out;
  std::vector<NodeId> node_origin;
  node_origin.reserve(nn + n_copies);
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) node_origin.push_back(v);
  for (std::size_t s = 0; s < fans.nodes.size(); ++s) {
    const NodeId n = fans.nodes[s];
    const Fans& fs = fans.of[s];
    const Vec3 p = mesh.point(n);
    for (std::size_t f = 0; f < fs.inward.size(); ++f) {
      const NodeId copy(static_cast<index_t>(points.size()));
      Vec3 centre = Vec3::Zero();
      double reach = 0, floor = 0;
      int count = 0;
      for (std::size_t k = 0; k < fs.around.size(); ++k) {
        if (static_cast<std::size_t>(fs.fan[k]) != f) continue;
        const CellId c = fs.around[k];
        const Vec3 x = cell_centroid(mesh, c);
        centre += x;
        reach += (x - p).norm();
        floor += size.min_length(c);
        ++count;
        cells[c.idx()][static_cast<std::size_t>(corner_of(mesh, c, n))] = copy;
      }
      centre /= count;
      reach /= count;
      const Vec3 d = copy_offset(boundary[n], fs.inward[f], centre - p, reach);
      points.push_back(p + copy_fraction(options, d.norm(), floor / count) * d);
      node_origin.push_back(n);
    }
  }
  out.node_origin = IdVector<NodeId, NodeId>(std::move(node_origin));

  std::vector<CellId> origin;
  origin.reserve(nc + faces.size());
  for (CellId c : id_range<CellId>(mesh.n_cells())) origin.push_back(c);
  for (const auto& [c, lf] : faces) {
    const auto f = mesh.face_nodes(c, lf);
    auto g = f;
    for (std::size_t i = 0; i < g.size(); ++i)
      g[i] = cells[c.idx()][static_cast<std::size_t>(corner_of(mesh, c, f[i]))];
    cells.push_back(layer_cell<M>(f, g));
    origin.push_back(c);
  }
  out.n_new_nodes = static_cast<index_t>(points.size()) - mesh.n_nodes();
  out.n_new_cells = static_cast<index_t>(faces.size());
  out.cell_origin = IdVector<CellId, CellId>(std::move(origin));
  out.mesh = M(std::move(points), std::move(cells));
  return out;
}

template PillowResult<QuadMesh> pillow_cells<QuadMesh>(const QuadMesh&,
                                                       const IdVector<CellId, char>&,
                                                       const IdVector<NodeId, NodeConstraint>&,
                                                       const PillowOptions&, const SizeCriterion&);
template PillowResult<HexMesh> pillow_cells<HexMesh>(const HexMesh&, const IdVector<CellId, char>&,
                                                     const IdVector<NodeId, NodeConstraint>&,
                                                     const PillowOptions&, const SizeCriterion&);

}  // namespace hexadapt
