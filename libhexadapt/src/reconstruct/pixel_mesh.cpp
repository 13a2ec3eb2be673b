#include "hexadapt/reconstruct/pixel_mesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/core/log.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/quality/scaled_jacobian.h"
#include "ref_cell.h"

namespace hexadapt::reconstruct {

using detail::ref_cell;
using detail::RefCell;

PixelMesh::PixelMesh(int dim, int nsub, int n_materials, const std::vector<CellId>& block_cells,
                     const std::vector<std::uint8_t>& block_free, index_t n_cells)
    : dim_(dim),
      nsub_(nsub),
      n_materials_(n_materials),
      cells_(block_cells),
      free_(block_free),
      cell_block_(static_cast<std::size_t>(n_cells), -1) {
  ppb_ = dim == 3 ? nsub * nsub * nsub : nsub * nsub;
  for (std::size_t b = 0; b < cells_.size(); ++b) cell_block_[cells_[b]] = static_cast<index_t>(b);
  const auto np = cells_.size() * static_cast<std::size_t>(ppb_);
  volume_.assign(np, 0.0);
  label_.assign(np, unassigned);
  corners_.assign(cells_.size() * static_cast<std::size_t>(ref_cell(dim).n_corners), Vec3::Zero());
  links_.assign(cells_.size() * static_cast<std::size_t>(2 * dim), FaceLink{});
}

std::array<int, 3> PixelMesh::lattice(std::int64_t p) const {
  auto l = static_cast<int>(p % ppb_);
  std::array<int, 3> ijk{{l % nsub_, (l / nsub_) % nsub_, 0}};
  if (dim_ == 3) ijk[2] = l / (nsub_ * nsub_);
  return ijk;
}

std::int64_t PixelMesh::pixel_at(index_t b, const std::array<int, 3>& ijk) const {
  return first_pixel(b) + ijk[0] + nsub_ * (ijk[1] + nsub_ * ijk[2]);
}

std::int64_t PixelMesh::neighbour(std::int64_t p, int lf) const {
  const RefCell& rc = ref_cell(dim_);
  const int a = rc.face_axis[static_cast<std::size_t>(lf)];
  const int side = rc.face_side[static_cast<std::size_t>(lf)];
  auto L = lattice(p);
  const index_t b = pixel_block(p);
  const auto ua = static_cast<std::size_t>(a);
  if (side == 0 && L[ua] > 0) {
    --L[ua];
    return pixel_at(b, L);
  }
  if (side == 1 && L[ua] < nsub_ - 1) {
    ++L[ua];
    return pixel_at(b, L);
  }
  const FaceLink& fl = link(b, lf);
  if (fl.block < 0) return -1;
  std::array<int, 3> M{{0, 0, 0}};
  for (std::size_t t = 0; t < static_cast<std::size_t>(dim_); ++t) {
    const int v = fl.axis[t] < 0 ? 0 : L[static_cast<std::size_t>(fl.axis[t])];
    M[t] = fl.flip[t] ? nsub_ - 1 - v : v;
  }
  return pixel_at(fl.block, M);
}

Vec3 PixelMesh::lattice_point(index_t b, const std::array<double, 3>& L) const {
  const RefCell& rc = ref_cell(dim_);
  const double n = nsub_;
  Vec3 x = Vec3::Zero();
  const auto base = static_cast<std::size_t>(b) * static_cast<std::size_t>(rc.n_corners);
  for (std::size_t v = 0; v < static_cast<std::size_t>(rc.n_corners); ++v) {
    double w = 1;
    for (std::size_t a = 0; a < static_cast<std::size_t>(dim_); ++a)
      w *= rc.corner[v][a] ? L[a] / n : 1 - L[a] / n;
    x += w * corners_[base + v];
  }
  return x;
}

Vec3 PixelMesh::centre(std::int64_t p) const {
  const auto L = lattice(p);
  return lattice_point(pixel_block(p), {{L[0] + 0.5, L[1] + 0.5, dim_ == 3 ? L[2] + 0.5 : 0.0}});
}

int default_nsub(int dim) {
  return dim == 3 ? 4 : 10;
}

namespace {

template <class M>
void check_inputs(const M& mesh, const Fractions& f, const CellMaterials& assignment) {
  if (f.n_cells() != mesh.n_cells())
    throw InputError("", "",
                     "fractions are given for " + std::to_string(f.n_cells()) +
                         " cells but the mesh has " + std::to_string(mesh.n_cells()));
  if (assignment.size() != static_cast<std::size_t>(mesh.n_cells()))
    throw InputError("", "",
                     "the material assignment has " + std::to_string(assignment.size()) +
                         " values but the mesh has " + std::to_string(mesh.n_cells()) + " cells");
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (assignment[c] < 0 || assignment[c] >= f.n_materials())
      throw InputError("", "cell " + std::to_string(c.value()),
                       "assigned material " + std::to_string(assignment[c]) + " is not in [0, " +
                           std::to_string(f.n_materials()) + ")");
}

/// Per cell: 0 plain, 1 fixed block (pure, shares a node with a mixed cell), 2 free block.
template <class M>
std::vector<std::uint8_t> pixelated_cells(const M& mesh, const Fractions& f) {
  std::vector<std::uint8_t> kind(static_cast<std::size_t>(mesh.n_cells()), 0);
  std::vector<std::uint8_t> near_mixed(static_cast<std::size_t>(mesh.n_nodes()), 0);
  parallel_for(mesh.n_cells(), [&](std::int64_t c) {
    if (!f.is_pure(CellId(c))) kind[static_cast<std::size_t>(c)] = 2;
  });
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (kind[c.idx()] == 2)
      for (NodeId n : mesh.cell_nodes(c)) near_mixed[n.idx()] = 1;
  parallel_for(mesh.n_cells(), [&](std::int64_t c) {
    auto& k = kind[static_cast<std::size_t>(c)];
    if (k == 2) return;
    for (NodeId n : mesh.cell_nodes(CellId(c)))
      if (near_mixed[n.idx()]) k = 1;
  });
  return kind;
}

std::string megabytes(double bytes) {
  std::ostringstream s;
  s.precision(1);
  s << std::fixed << bytes / 1e6 << " MB";
  return s.str();
}

}  // namespace

namespace {

// The plan of n_blocks pixelated cells, n_free_blocks of them mixed, in a mesh of n_cells.
PixelPlan counted_plan(int dim, int nsub, std::int64_t n_cells, index_t n_blocks,
                       index_t n_free_blocks, const PixelOptions& options) {
  PixelPlan plan;
  plan.dim = dim;
  plan.nsub = nsub;
  plan.n_blocks = n_blocks;
  plan.n_free_blocks = n_free_blocks;
  std::int64_t ppb = plan.nsub;
  for (int a = 1; a < dim; ++a) ppb *= plan.nsub;
  plan.n_pixels = ppb * plan.n_blocks;
  plan.n_free_pixels = ppb * plan.n_free_blocks;
  const int nodes_per_cell = 1 << dim, faces_per_cell = 2 * dim;
  const double per_block = 4.0 + 1.0 + 24.0 * nodes_per_cell + 8.0 * faces_per_cell;
  const double per_pixel = 8.0 + 4.0 + options.output_bytes_per_pixel;
  plan.bytes = 4.0 * static_cast<double>(n_cells) + per_block * plan.n_blocks +
               per_pixel * static_cast<double>(plan.n_pixels) +
               options.method_bytes_per_free_pixel * static_cast<double>(plan.n_free_pixels);
  return plan;
}

int checked_nsub(int dim, const PixelOptions& options) {
  const int nsub = options.nsub == 0 ? default_nsub(dim) : options.nsub;
  if (nsub < 1 || nsub > 64)
    throw OptionError("nsub must be in [1, 64], got " + std::to_string(nsub));
  return nsub;
}

template <class M>
PixelPlan plan_of(const M& mesh, const std::vector<std::uint8_t>& pix,
                  const PixelOptions& options) {
  const int nsub = checked_nsub(M::dim, options);
  index_t n_blocks = 0, n_free_blocks = 0;
  for (auto v : pix) {
    n_blocks += v ? 1 : 0;
    n_free_blocks += v == 2 ? 1 : 0;
  }
  return counted_plan(M::dim, nsub, mesh.n_cells(), n_blocks, n_free_blocks, options);
}

// Parallelepiped cells (every Cartesian and rectilinear cell) split into equal pixels.
template <std::size_t N>
bool is_affine(const std::array<Vec3, N>& x, const detail::RefCell& rc) {
  const Vec3 o = x[0];
  Vec3 e[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (std::size_t v = 0; v < N; ++v) {
    int bits = 0, axis = -1;
    for (int a = 0; a < rc.dim; ++a)
      if (rc.corner[v][static_cast<std::size_t>(a)]) {
        ++bits;
        axis = a;
      }
    if (bits == 1) e[axis] = x[v] - o;
  }
  double scale = 0;
  for (const Vec3& d : e) scale = std::max(scale, d.norm());
  for (std::size_t v = 0; v < N; ++v) {
    Vec3 want = o;
    for (int a = 0; a < rc.dim; ++a)
      if (rc.corner[v][static_cast<std::size_t>(a)]) want += e[a];
    if ((x[v] - want).norm() > 1e-12 * scale) return false;
  }
  return true;
}

}  // namespace

template <class M>
PixelPlan plan_pixels(const M& mesh, const Fractions& fractions, const CellMaterials& assignment,
                      const PixelOptions& options) {
  check_inputs(mesh, fractions, assignment);
  return plan_of(mesh, pixelated_cells(mesh, fractions), options);
}

template <class M>
std::vector<double> owned_cell_bytes(const M& mesh, const Fractions& fractions,
                                     const CellMaterials& assignment, const PixelOptions& options,
                                     const dist::Block& block) {
  check_inputs(mesh, fractions, assignment);
  const int nsub = checked_nsub(M::dim, options);
  double bytes[3];  // a plain cell, a pixelated pure one, a mixed one
  for (int kind = 0; kind < 3; ++kind)
    bytes[kind] = counted_plan(M::dim, nsub, 1, kind > 0 ? 1 : 0, kind == 2 ? 1 : 0, options).bytes;
  const std::vector<std::uint8_t> kind = pixelated_cells(mesh, fractions);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(block.owned_cell_end - block.owned_cell_first));
  for (index_t c = block.owned_cell_first; c < block.owned_cell_end; ++c)
    out.push_back(bytes[kind[static_cast<std::size_t>(c)]]);
  return out;
}

void check_pixel_memory(const PixelPlan& plan, const PixelOptions& options) {
  if (plan.bytes > options.max_memory)
    throw ResourceError("the sub-pixel mesh needs about " + megabytes(plan.bytes) + " (" +
                        std::to_string(plan.n_pixels) + " pixels, nsub " +
                        std::to_string(plan.nsub) + "), more than the allowed " +
                        megabytes(options.max_memory) + ": lower {nsub} or raise {max_memory}");
}

PixelPlan whole_plan(const PixelMesh& pixels, const PixelOptions& options,
                     const dist::Distribution& where) {
  std::int64_t counts[2] = {0, 0};
  for (index_t b = 0; b < pixels.n_blocks(); ++b)
    if (where.block.owns(pixels.block_cell(b))) {
      ++counts[0];
      counts[1] += pixels.block_free(b) ? 1 : 0;
    }
  const std::int64_t owned = where.block.owned_cell_end - where.block.owned_cell_first;
  return counted_plan(pixels.dim(), pixels.nsub(), dist::sum_in_rank_order(where.comm, owned),
                      static_cast<index_t>(dist::sum_in_rank_order(where.comm, counts[0])),
                      static_cast<index_t>(dist::sum_in_rank_order(where.comm, counts[1])),
                      options);
}

template <class M>
FaceLink face_link(const M& mesh, CellId c, int lf) {
  const RefCell& rc = ref_cell(M::dim);
  FaceLink fl;
  const CellId o = mesh.neighbour(c, lf);
  if (!o.valid()) return fl;
  const auto a_nodes = mesh.cell_nodes(c);
  const auto b_nodes = mesh.cell_nodes(o);
  auto pos_b = [&](int va) {
    const NodeId n = a_nodes[static_cast<std::size_t>(va)];
    for (std::size_t v = 0; v < b_nodes.size(); ++v)
      if (b_nodes[v] == n) return rc.corner[v];
    throw InternalError("neighbouring cells do not share a face node");
  };
  const auto& face = rc.face[static_cast<std::size_t>(lf)];
  const int normal = rc.face_axis[static_cast<std::size_t>(lf)];
  // a0: the face corner at tangent coordinates 0; a1[t]: one step along tangent axis t.
  int a0 = -1;
  std::array<int, 3> a1{{-1, -1, -1}};
  for (int i = 0; i < rc.nodes_per_face; ++i) {
    const int v = face[static_cast<std::size_t>(i)];
    int ones = 0, last = -1;
    for (int t = 0; t < M::dim; ++t)
      if (t != normal && rc.corner[static_cast<std::size_t>(v)][static_cast<std::size_t>(t)]) {
        ++ones;
        last = t;
      }
    if (ones == 0) a0 = v;
    if (ones == 1) a1[static_cast<std::size_t>(last)] = v;
  }
  const auto p0 = pos_b(a0);
  for (std::size_t s = 0; s < static_cast<std::size_t>(M::dim); ++s) {
    fl.flip[s] = static_cast<std::int8_t>(p0[s]);
    for (int t = 0; t < M::dim; ++t)
      if (t != normal && pos_b(a1[static_cast<std::size_t>(t)])[s] != p0[s])
        fl.axis[s] = static_cast<std::int8_t>(t);
  }
  return fl;
}

template <class M>
PixelMesh build_pixel_mesh(const M& mesh, const Fractions& fractions,
                           const CellMaterials& assignment, const PixelOptions& options,
                           PixelPlan* plan_out) {
  check_inputs(mesh, fractions, assignment);
  const auto pix = pixelated_cells(mesh, fractions);
  const PixelPlan plan = plan_of(mesh, pix, options);
  if (plan_out) *plan_out = plan;
  log_info("pixels: " + std::to_string(plan.n_pixels) + " in " + std::to_string(plan.n_blocks) +
           " cells (" + std::to_string(plan.n_free_pixels) + " free), nsub " +
           std::to_string(plan.nsub) + ", estimated memory " + megabytes(plan.bytes));
  check_pixel_memory(plan, options);
  std::vector<CellId> cells;
  std::vector<std::uint8_t> free;
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (pix[c.idx()]) {
      cells.push_back(c);
      free.push_back(pix[c.idx()] == 2 ? 1 : 0);
    }
  PixelMesh pm(M::dim, plan.nsub, fractions.n_materials(), cells, free, mesh.n_cells());
  const RefCell& rc = ref_cell(M::dim);
  const auto npc = static_cast<std::size_t>(rc.n_corners);
  const auto nf = static_cast<std::size_t>(rc.n_faces);
  auto& corners = pm.block_corners();
  auto& links = pm.block_links();
  auto& volumes = pm.volumes();
  parallel_for(pm.n_blocks(), [&](std::int64_t bi) {
    const auto b = static_cast<index_t>(bi);
    const CellId c = pm.block_cell(b);
    const auto nodes = mesh.cell_nodes(c);
    for (std::size_t v = 0; v < npc; ++v)
      corners[static_cast<std::size_t>(b) * npc + v] = mesh.point(nodes[v]);
    for (std::size_t lf = 0; lf < nf; ++lf) {
      FaceLink fl = face_link(mesh, c, static_cast<int>(lf));
      const CellId o = mesh.neighbour(c, static_cast<int>(lf));
      if (o.valid()) fl.block = pm.cell_block(o);
      links[static_cast<std::size_t>(b) * nf + lf] = fl;
    }
  });
  parallel_for(pm.n_blocks(), [&](std::int64_t bi) {
    const auto b = static_cast<index_t>(bi);
    const CellId c = pm.block_cell(b);
    const int fixed = pm.block_free(b) ? PixelMesh::unassigned : assignment[c];
    const bool affine = is_affine(mesh.cell_points(c), rc);
    const double equal = mesh.cell_volume(c) / pm.pixels_per_block();
    for (std::int64_t p = pm.first_pixel(b); p < pm.first_pixel(b + 1); ++p) {
      pm.set_label(p, fixed);
      if (affine) {
        volumes[static_cast<std::size_t>(p)] = equal;
        continue;
      }
      const auto L = pm.lattice(p);
      std::array<Vec3, 8> x;
      for (std::size_t v = 0; v < npc; ++v)
        x[v] = pm.lattice_point(b, {{double(L[0] + rc.corner[v][0]), double(L[1] + rc.corner[v][1]),
                                     double(L[2] + rc.corner[v][2])}});
      volumes[static_cast<std::size_t>(p)] =
          M::dim == 3 ? hex_volume(x) : quad_area({x[0], x[1], x[2], x[3]});
    }
  });
  double width = 0;
  for (double v : volumes) width += std::pow(std::abs(v), 1.0 / M::dim);
  if (!volumes.empty()) pm.set_mean_width(width / static_cast<double>(volumes.size()));
  return pm;
}

template PixelPlan plan_pixels(const QuadMesh&, const Fractions&, const CellMaterials&,
                               const PixelOptions&);
template PixelPlan plan_pixels(const HexMesh&, const Fractions&, const CellMaterials&,
                               const PixelOptions&);
template std::vector<double> owned_cell_bytes(const QuadMesh&, const Fractions&,
                                              const CellMaterials&, const PixelOptions&,
                                              const dist::Block&);
template std::vector<double> owned_cell_bytes(const HexMesh&, const Fractions&,
                                              const CellMaterials&, const PixelOptions&,
                                              const dist::Block&);
template PixelMesh build_pixel_mesh(const QuadMesh&, const Fractions&, const CellMaterials&,
                                    const PixelOptions&, PixelPlan*);
template PixelMesh build_pixel_mesh(const HexMesh&, const Fractions&, const CellMaterials&,
                                    const PixelOptions&, PixelPlan*);
template FaceLink face_link(const QuadMesh&, CellId, int);
template FaceLink face_link(const HexMesh&, CellId, int);

}  // namespace hexadapt::reconstruct
