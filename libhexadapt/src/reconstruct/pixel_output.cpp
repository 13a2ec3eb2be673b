#include "hexadapt/reconstruct/pixel_output.h"

#include "ref_cell.h"

namespace hexadapt::reconstruct {

double pixel_output_bytes_per_pixel(int dim) { return dim == 3 ? 160.0 : 110.0; }

io::MeshData pixel_mesh_data(const PixelMesh& px) {
  return pixel_mesh_data(px, dist::Block::whole(px.n_cells(), 0));
}

io::MeshData pixel_mesh_data(const PixelMesh& px, const dist::Block& block) {
  const auto& rc = detail::ref_cell(px.dim());
  const int n = px.nsub();
  const int nk = px.dim() == 3 ? n + 1 : 1;
  const std::int64_t points_per_block = static_cast<std::int64_t>(n + 1) * (n + 1) * nk;
  io::MeshData d;
  d.dim = px.dim();
  d.points.reserve(static_cast<std::size_t>(points_per_block * px.n_blocks()));
  d.cells.reserve(static_cast<std::size_t>(px.n_pixels() * rc.n_corners));
  io::DataArray material{"material", 1, io::ScalarType::int32, {}};
  io::DataArray parent{"parent", 1, io::ScalarType::int32, {}};
  io::DataArray free{"free", 1, io::ScalarType::uint8, {}};
  for (index_t b = 0; b < px.n_blocks(); ++b) {
    if (!block.owns(px.block_cell(b))) continue;
    const auto base = static_cast<std::int64_t>(d.points.size());
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) d.points.push_back(px.lattice_point(b, {{double(i), double(j), double(k)}}));
    for (std::int64_t p = px.first_pixel(b); p < px.first_pixel(b + 1); ++p) {
      const auto L = px.lattice(p);
      for (int v = 0; v < rc.n_corners; ++v) {
        const auto& o = rc.corner[static_cast<std::size_t>(v)];
        d.cells.push_back(NodeId(base + (L[0] + o[0]) + (n + 1) * ((L[1] + o[1]) + (n + 1) * (L[2] + o[2]))));
      }
      material.values.push_back(px.label(p));
      parent.values.push_back(static_cast<double>(block.global(px.block_cell(b))));
      free.values.push_back(px.block_free(b) ? 1 : 0);
    }
  }
  d.cell_data = {std::move(material), std::move(parent), std::move(free)};
  return d;
}

}  // namespace hexadapt::reconstruct
