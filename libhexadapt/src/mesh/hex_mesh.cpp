#include "hexadapt/mesh/hex_mesh.h"

#include <algorithm>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

namespace {

std::array<NodeId, 4> sorted(std::array<NodeId, 4> f) {
  std::sort(f.begin(), f.end());
  return f;
}

void check_cells(const std::vector<HexMesh::CellNodes>& cells, index_t n_nodes) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    HexMesh::CellNodes s = cells[c];
    for (NodeId n : s)
      if (!n.valid() || n.value() >= n_nodes)
        throw MeshError("cell " + std::to_string(c) + " refers to node " +
                        std::to_string(n.value()) + " but the mesh has " +
                        std::to_string(n_nodes) + " nodes");
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end())
      throw MeshError("cell " + std::to_string(c) + " repeats a node");
  }
}

}  // namespace

HexMesh::HexMesh(std::vector<Vec3> points, std::vector<CellNodes> cells)
    : points_(std::move(points)), cells_(std::move(cells)) {
  checked_index(cells_.size() * 6, "hex half-faces");
  check_cells(cells_, n_nodes());
  opposite_.assign(cells_.size() * 6, HalfFaceId::invalid());
  std::vector<std::string> errors(cells_.size());
  // Each half-face looks for the other cell holding the same 4 nodes around its smallest
  // node; every half-face writes only its own slot, so the loop is order-independent.
  parallel_for(n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    for (int lf = 0; lf < 6; ++lf) {
      const auto key = sorted(face_nodes(c, lf));
      int found = 0;
      for (CellId c2 : node_cells(key[0])) {
        if (c2 == c) continue;
        for (int lf2 = 0; lf2 < 6; ++lf2) {
          if (sorted(face_nodes(c2, lf2)) != key) continue;
          if (++found == 1) opposite_[half_face(c, lf).idx()] = half_face(c2, lf2);
        }
      }
      if (found > 1 && errors[c.idx()].empty())
        errors[c.idx()] = "face " + std::to_string(lf) + " of cell " + std::to_string(i) +
                          " is shared by " + std::to_string(found + 1) +
                          " cells (non-manifold)";
    }
  });
  for (const auto& e : errors)
    if (!e.empty()) throw MeshError(e);
}

HexMesh::FaceNodes HexMesh::face_nodes(CellId c, int lf) const {
  const auto& v = cells_[c.idx()];
  const auto& f = ref_hex::face_nodes[static_cast<std::size_t>(lf)];
  return {v[static_cast<std::size_t>(f[0])], v[static_cast<std::size_t>(f[1])],
          v[static_cast<std::size_t>(f[2])], v[static_cast<std::size_t>(f[3])]};
}

std::vector<HalfFaceId> HexMesh::boundary_half_faces() const {
  std::vector<HalfFaceId> out;
  for (std::size_t h = 0; h < opposite_.size(); ++h)
    if (!opposite_[h].valid()) out.push_back(HalfFaceId(h));
  return out;
}

Span<CellId> HexMesh::node_cells(NodeId n) const {
  return node_cells_
      .get([this] {
        std::vector<NodeId> flat;
        flat.reserve(cells_.size() * 8);
        for (const auto& c : cells_) flat.insert(flat.end(), c.begin(), c.end());
        return NodeCells(flat, 8, n_nodes());
      })
      .of(n);
}

std::array<Vec3, 8> HexMesh::cell_points(CellId c) const {
  std::array<Vec3, 8> p;
  const auto& v = cells_[c.idx()];
  for (std::size_t i = 0; i < 8; ++i) p[i] = points_[v[i].idx()];
  return p;
}

double HexMesh::cell_volume(CellId c) const { return hex_volume(cell_points(c)); }

double HexMesh::cell_quality(CellId c) const { return hex_scaled_jacobian(cell_points(c)); }

}  // namespace hexadapt
