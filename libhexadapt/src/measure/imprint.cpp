// Exact imprint of an output mesh onto the input cells (see imprint.h).
#include "hexadapt/measure/imprint.h"

#include <array>
#include <cmath>

#include "cell_bins.h"
#include "cell_pieces.h"
#include "cell_values.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel_progress.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt {

namespace {

using clip::Plane;
using Pieces = std::vector<clip::Piece>;

// Boxes overlapping with positive volume (area: the z extents of 2D boxes are empty).
bool overlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, int dim) {
  for (int k = 0; k < dim; ++k)
    if (a.max()[k] <= b.min()[k] || b.max()[k] <= a.min()[k]) return false;
  return true;
}

// Volume of a positively oriented tet inside one convex piece; the tet is only clipped by
// the planes it straddles.
double tet_in_piece(const clip::Tet& t, const Eigen::AlignedBox3d& box, const clip::Piece& piece) {
  if (!overlap(box, piece.box, 3)) return 0;
  std::array<const Plane*, 16> cuts;
  std::size_t n_cuts = 0;
  for (const Plane& pl : piece.planes) {
    int out = 0, in = 0;
    for (const Vec3& p : t.p) {
      const double s = pl.side(p);
      out += s >= 0;
      in += s <= 0;
    }
    if (out == 4) return 0;  // wholly outside this plane
    if (in < 4) cuts[n_cuts++] = &pl;
  }
  if (n_cuts == 0) return clip::tet_volume(t.p[0], t.p[1], t.p[2], t.p[3]);
  double v = 0;
  if (clip::clipped_tet_volume(t.p[0], t.p[1], t.p[2], t.p[3], cuts.data(), n_cuts, &v)) return v;
  // Per-thread buffers: clipping allocates nothing once they have grown.
  thread_local clip::Polyhedron poly, scratch;
  clip::tetrahedron(t.p[0], t.p[1], t.p[2], t.p[3], poly);
  for (std::size_t k = 0; k < n_cuts; ++k) {
    clip::clip_polyhedron(poly, *cuts[k], scratch);
    if (poly.n_faces() < 4) return 0;
  }
  return clip::polyhedron_volume(poly);
}

double hex_in_pieces(const io::MeshData& output, index_t o, const Pieces& pieces) {
  double v = 0;
  for (const clip::Tet& t : clip::hex_tets(output, o)) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : t.p) box.extend(p);
    double in = 0;
    for (const auto& piece : pieces) in += piece.sign * tet_in_piece(t, box, piece);
    v += t.sign * in;
  }
  return v;
}

double quad_in_pieces(const io::MeshData& output, index_t o, const Pieces& pieces) {
  double sign = 1;
  const clip::Polygon q = clip::quad_polygon(output, o, &sign);
  clip::Polygon a, b;
  double v = 0;
  for (const auto& piece : pieces) {
    a = q;
    for (const Plane& pl : piece.planes) {
      clip::clip_polygon(a, pl, b);
      std::swap(a, b);
      if (a.size() < 3) break;
    }
    v += piece.sign * clip::polygon_area(a);
  }
  return sign * v;
}

double output_cell_volume(const io::MeshData& output, index_t o) {
  if (output.dim == 2) {
    double sign = 1;
    const clip::Polygon q = clip::quad_polygon(output, o, &sign);
    return sign * clip::polygon_area(q);
  }
  double v = 0;
  for (const clip::Tet& t : clip::hex_tets(output, o))
    v += t.sign * clip::tet_volume(t.p[0], t.p[1], t.p[2], t.p[3]);
  return v;
}

void check_inputs(const io::MeshData& input, const io::MeshData& output,
                  const CellMaterials& material, int n_materials) {
  if (input.dim == 0 || output.dim == 0) throw InputError({}, {}, "imprint: a mesh has no cells");
  if (input.dim != output.dim)
    throw InputError({}, {},
                     "imprint: the reference grid is " + std::to_string(input.dim) +
                         "D but the mesh is " + std::to_string(output.dim) + "D");
  for (const io::MeshData* d : {&input, &output})
    for (std::size_t i = 0; i < d->cells.size(); ++i)
      if (!d->cells[i].valid() || d->cells[i].value() >= d->n_points())
        throw InputError(
            {}, "cell " + std::to_string(i / static_cast<std::size_t>(d->nodes_per_cell())),
            "node " + std::to_string(d->cells[i].value()) + " does not exist (" +
                std::to_string(d->n_points()) + " points)");
  if (material.size() != static_cast<std::size_t>(output.n_cells()))
    throw InputError({}, {},
                     "imprint: " + std::to_string(material.size()) + " materials given for " +
                         std::to_string(output.n_cells()) + " cells");
  for (CellId o : id_range<CellId>(output.n_cells()))
    if (material[o] < 0 || material[o] >= n_materials)
      throw InputError({}, "cell " + std::to_string(o.value()),
                       "material " + std::to_string(material[o]) + " is not in [0, " +
                           std::to_string(n_materials) + ")");
}

Imprint imprint_as_given(const io::MeshData& input, const io::MeshData& output,
                         const CellMaterials& material, int n_materials,
                         const ImprintOptions& options) {
  Imprint r;
  r.n_materials = n_materials;
  r.n_cells = input.n_cells();
  const auto n_mat = static_cast<std::size_t>(n_materials);
  r.volume.assign(static_cast<std::size_t>(r.n_cells) * n_mat, 0.0);
  r.cell_volume.assign(static_cast<std::size_t>(r.n_cells), 0.0);
  r.output_volume.assign(n_mat, 0.0);
  for (index_t o = 0; o < output.n_cells(); ++o)
    r.output_volume[static_cast<std::size_t>(material[CellId(o)])] += output_cell_volume(output, o);
  const CellBins bins(output, options.bins_per_cell);
  parallel_for_progress(r.n_cells, options.progress, "imprint", [&](std::int64_t i) {
    const auto c = static_cast<index_t>(i);
    double volume = 0;
    const Pieces pieces = clip::convex_pieces(input, c, options.convex_tolerance, &volume);
    r.cell_volume[static_cast<std::size_t>(c)] = volume;
    std::vector<index_t> candidates;
    bins.query(cell_box(input, c), candidates);
    double* slot = r.volume.data() + static_cast<std::size_t>(c) * n_mat;
    for (index_t o : candidates) {
      const double v =
          input.dim == 3 ? hex_in_pieces(output, o, pieces) : quad_in_pieces(output, o, pieces);
      slot[material[CellId(o)]] += v;
    }
  });
  return r;
}

}  // namespace

Imprint imprint(const io::MeshData& input, const io::MeshData& output,
                const CellMaterials& material, int n_materials, const ImprintOptions& options) {
  check_inputs(input, output, material, n_materials);
  const UnitFrame frame = far_unit_frame(input.points);
  if (frame.is_identity()) return imprint_as_given(input, output, material, n_materials, options);
  Imprint r = imprint_as_given(geometry_in_frame(input, frame), geometry_in_frame(output, frame),
                               material, n_materials, options);
  r.volume_exponent = frame.exponent * input.dim;
  return r;
}

}  // namespace hexadapt
