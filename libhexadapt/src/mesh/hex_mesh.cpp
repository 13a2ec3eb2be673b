#include "hexadapt/mesh/hex_mesh.h"

#include <algorithm>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

namespace {

// Bit mask of the local nodes of each local face.
constexpr std::array<unsigned, 6> face_masks = [] {
  std::array<unsigned, 6> m{};
  for (std::size_t lf = 0; lf < 6; ++lf)
    for (int v : ref_hex::face_nodes[lf]) m[lf] |= 1u << v;
  return m;
}();

// The local face of `cell` made of the nodes `face` (in any order), or -1. A cell without
// the face's third node (diagonal to the first) is told at once: most cells around a node
// hold none of its faces.
int local_face_of(const HexMesh::CellNodes& cell, const HexMesh::FaceNodes& face) {
  if (std::find(cell.begin(), cell.end(), face[2]) == cell.end()) return -1;
  unsigned mask = 0;
  for (std::size_t k = 0; k < 8; ++k)
    for (NodeId n : face) mask |= static_cast<unsigned>(cell[k] == n) << k;
  for (int lf = 0; lf < 6; ++lf)
    if (face_masks[static_cast<std::size_t>(lf)] == mask) return lf;
  return -1;
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
  std::vector<std::int8_t> shared_face(cells_.size(), -1);  // a face with 3+ cells
  // Each half-face looks for the other cell holding its 4 nodes among the cells around one
  // of them; every half-face writes only its own slot, so the loop is order-independent.
  parallel_for(n_cells(), [&](std::int64_t i) {
    const CellId c(i);
    for (int lf = 0; lf < 6; ++lf) {
      const FaceNodes f = face_nodes(c, lf);
      int found = 0;
      for (CellId c2 : node_cells(f[0])) {
        if (c2 == c) continue;
        const int lf2 = local_face_of(cells_[c2.idx()], f);
        if (lf2 >= 0 && ++found == 1) opposite_[half_face(c, lf).idx()] = half_face(c2, lf2);
      }
      if (found > 1) shared_face[c.idx()] = static_cast<std::int8_t>(lf);
    }
  });
  for (std::size_t c = 0; c < shared_face.size(); ++c)
    if (shared_face[c] >= 0)
      throw MeshError("face " + std::to_string(shared_face[c]) + " of cell " + std::to_string(c) +
                      " is shared by more than two cells (non-manifold)");
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
