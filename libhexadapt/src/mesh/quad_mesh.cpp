#include "hexadapt/mesh/quad_mesh.h"

#include <algorithm>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

namespace {

// OpenMesh refuses non-manifold or inconsistently oriented faces (and prints about it);
// find them first so the error names the cell and the edge.
void check_cells(const std::vector<QuadMesh::CellNodes>& cells, index_t n_nodes) {
  std::vector<NodeId> flat;
  flat.reserve(cells.size() * 4);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    auto s = cells[c];
    for (NodeId n : s)
      if (!n.valid() || n.value() >= n_nodes)
        throw MeshError("cell " + std::to_string(c) + " refers to node " +
                        std::to_string(n.value()) + " but the mesh has " +
                        std::to_string(n_nodes) + " nodes");
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end())
      throw MeshError("cell " + std::to_string(c) + " repeats a node");
    flat.insert(flat.end(), cells[c].begin(), cells[c].end());
  }
  const NodeCells around(flat, 4, n_nodes);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (std::size_t e = 0; e < 4; ++e) {
      const NodeId a = cells[c][e], b = cells[c][(e + 1) % 4];
      int same = 0, reverse = 0;
      for (CellId o : around.of(a)) {
        if (o.idx() == c) continue;
        for (std::size_t k = 0; k < 4; ++k) {
          const NodeId p = cells[o.idx()][k], q = cells[o.idx()][(k + 1) % 4];
          same += (p == a && q == b);
          reverse += (p == b && q == a);
        }
      }
      const std::string edge = "edge (" + std::to_string(a.value()) + ", " +
                               std::to_string(b.value()) + ") of cell " + std::to_string(c);
      if (same + reverse > 1)
        throw MeshError(edge + " is shared by more than two cells (non-manifold)");
      if (same > 0)
        throw MeshError(edge + " is listed in the same direction by a neighbour: cells are "
                        "not consistently oriented");
    }
  }
}

}  // namespace

QuadMesh::QuadMesh(std::vector<Vec3> points, std::vector<CellNodes> cells) {
  checked_index(cells.size() * 4, "quad edges");
  const index_t n_nodes = checked_index(points.size(), "nodes");
  check_cells(cells, n_nodes);
  om_.reserve(points.size(), cells.size() * 2 + points.size(), cells.size());
  for (const Vec3& p : points) om_.add_vertex(OmPolyMesh::Point(p.x(), p.y(), p.z()));
  for (std::size_t c = 0; c < cells.size(); ++c) {
    std::vector<OmPolyMesh::VertexHandle> vh;
    for (NodeId n : cells[c]) vh.emplace_back(n.value());
    if (!om_.add_face(vh).is_valid())
      throw MeshError("cell " + std::to_string(c) +
                      " cannot be added: non-manifold vertex configuration");
  }
}

QuadMesh::CellNodes QuadMesh::cell_nodes(CellId c) const {
  CellNodes out;
  std::size_t k = 0;
  // add_face makes the face's halfedge the one ending at the first node given.
  for (auto v : om_.fv_range(OmPolyMesh::FaceHandle(c.value()))) out[k++] = NodeId(v.idx());
  return out;
}

QuadMesh::FaceNodes QuadMesh::face_nodes(CellId c, int lf) const {
  const auto v = cell_nodes(c);
  return {v[static_cast<std::size_t>(lf)], v[static_cast<std::size_t>((lf + 1) % 4)]};
}

OmPolyMesh::HalfedgeHandle QuadMesh::edge_halfedge(CellId c, int lf) const {
  auto h = om_.halfedge_handle(OmPolyMesh::FaceHandle(c.value()));
  // h ends at node 0, so it is edge 3; the next one is edge 0.
  for (int k = 0; k <= lf; ++k) h = om_.next_halfedge_handle(h);
  return h;
}

CellId QuadMesh::neighbour(CellId c, int lf) const {
  const auto f = om_.face_handle(om_.opposite_halfedge_handle(edge_halfedge(c, lf)));
  return f.is_valid() ? CellId(f.idx()) : CellId::invalid();
}

Span<CellId> QuadMesh::node_cells(NodeId n) const {
  return node_cells_
      .get([this] {
        std::vector<NodeId> flat;
        flat.reserve(static_cast<std::size_t>(n_cells()) * 4);
        for (CellId c : id_range<CellId>(n_cells())) {
          const auto v = cell_nodes(c);
          flat.insert(flat.end(), v.begin(), v.end());
        }
        return NodeCells(flat, 4, n_nodes());
      })
      .of(n);
}

Vec3 QuadMesh::point(NodeId n) const {
  const auto& p = om_.point(OmPolyMesh::VertexHandle(n.value()));
  return Vec3(p[0], p[1], p[2]);
}

void QuadMesh::set_point(NodeId n, const Vec3& p) {
  om_.set_point(OmPolyMesh::VertexHandle(n.value()), OmPolyMesh::Point(p.x(), p.y(), p.z()));
}

std::array<Vec3, 4> QuadMesh::cell_points(CellId c) const {
  const auto v = cell_nodes(c);
  return {point(v[0]), point(v[1]), point(v[2]), point(v[3])};
}

double QuadMesh::cell_volume(CellId c) const { return quad_area(cell_points(c)); }

double QuadMesh::cell_quality(CellId c) const { return quad_scaled_jacobian(cell_points(c)); }

}  // namespace hexadapt
