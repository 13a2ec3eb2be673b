#include "hexadapt/generate/extrusion.h"

#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt::generate {

io::MeshData extrude(const io::MeshData& quads, int layers, double thickness, double z0) {
  if (quads.dim != 2) throw OptionError("extrusion sweeps quads: the mesh is not 2D");
  if (layers < 1)
    throw OptionError("extrusion needs at least one layer, got " + std::to_string(layers));
  if (!(thickness > 0)) throw OptionError("extrusion layer thickness must be positive");
  const std::size_t nn = quads.points.size(), nq = static_cast<std::size_t>(quads.n_cells());
  const auto n_layers = static_cast<std::size_t>(layers);
  io::MeshData out;
  out.dim = 3;
  out.points.reserve(nn * (n_layers + 1));
  for (std::size_t l = 0; l <= n_layers; ++l)
    for (const Vec3& q : quads.points)
      out.points.emplace_back(q.x(), q.y(), z0 + thickness * static_cast<double>(l));
  out.cells.reserve(nq * n_layers * 8);
  // counter-clockwise 0 1 2 3 is binary 0 1 3 2 in the bottom and top faces
  constexpr std::array<std::size_t, 4> binary = {0, 1, 3, 2};
  for (std::size_t l = 0; l < n_layers; ++l)
    for (std::size_t c = 0; c < nq; ++c)
      for (std::size_t layer : {l, l + 1})
        for (std::size_t k : binary)
          out.cells.push_back(
              NodeId(static_cast<std::int64_t>(layer * nn) + quads.cells[4 * c + k].value()));
  return out;
}

}  // namespace hexadapt::generate
