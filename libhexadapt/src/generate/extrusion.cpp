#include "hexadapt/generate/extrusion.h"

#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt::generate {

HexMesh extrude(const QuadMesh& mesh, int layers, double thickness, double z0) {
  if (layers < 1) throw OptionError("extrusion needs at least one layer, got " + std::to_string(layers));
  if (!(thickness > 0)) throw OptionError("extrusion layer thickness must be positive");
  const index_t nn = mesh.n_nodes();
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(nn) * static_cast<std::size_t>(layers + 1));
  for (int l = 0; l <= layers; ++l)
    for (NodeId n : id_range<NodeId>(nn)) {
      Vec3 p = mesh.point(n);
      p.z() = z0 + thickness * l;
      points.push_back(p);
    }
  std::vector<HexMesh::CellNodes> cells;
  cells.reserve(static_cast<std::size_t>(mesh.n_cells()) * static_cast<std::size_t>(layers));
  for (int l = 0; l < layers; ++l)
    for (CellId c : id_range<CellId>(mesh.n_cells())) {
      const auto q = mesh.cell_nodes(c);
      // counter-clockwise 0 1 2 3 is binary 0 1 3 2 in the bottom and top faces
      const auto at = [&](int layer, int k) {
        return NodeId(static_cast<std::int64_t>(layer) * nn + q[static_cast<std::size_t>(k)].value());
      };
      cells.push_back({at(l, 0), at(l, 1), at(l, 3), at(l, 2), at(l + 1, 0), at(l + 1, 1),
                       at(l + 1, 3), at(l + 1, 2)});
    }
  return HexMesh(std::move(points), std::move(cells));
}

}  // namespace hexadapt::generate
