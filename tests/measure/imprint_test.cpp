// Imprint and discrepancy: exact self-imprints, per-output-cell volume sums, conservation
// per material, independent Monte-Carlo estimates (point location by inverse bilinear /
// affine maps, not by clipping), a dart-shaped input cell, and the analytic discrepancy of
// a straight interface moved by a known offset.
#include "hexadapt/measure/imprint.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <random>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/discrepancy.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/measure/target_distance.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

io::MeshData quads(int nx, int ny, double sx = 1, double sy = 1) {
  return io::from_mesh(make_quad_grid(nx, ny, Vec3::Zero(), Vec3(sx, sy, 1)));
}
io::MeshData hexes(int nx, int ny, int nz, double s = 1) {
  return io::from_mesh(make_hex_grid(nx, ny, nz, Vec3::Zero(), Vec3(s, s, s)));
}

void jitter(io::MeshData& d, double amount, unsigned seed, bool keep_z = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Vec3& p : d.points) {
    p.x() += u(rng);
    p.y() += u(rng);
    if (d.dim == 3 && !keep_z) p.z() += u(rng);
  }
}

void transform(io::MeshData& d, const Eigen::Matrix3d& a, const Vec3& shift) {
  for (Vec3& p : d.points) p = a * p + shift;
}

Eigen::Matrix3d rotation(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

CellMaterials pattern(index_t n, int n_materials) {
  CellMaterials m(static_cast<std::size_t>(n));
  for (CellId c : id_range<CellId>(n)) m[c] = (c.value() * 7 + c.value() / 3) % n_materials;
  return m;
}

CellMaterials materials(std::vector<int> m) {
  return CellMaterials(std::move(m));
}

double total(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}

// Self-imprint: every input cell holds its own material only, with its whole volume.
void expect_pure_self_imprint(const io::MeshData& grid) {
  const int n_mat = 3;
  const CellMaterials m = pattern(grid.n_cells(), n_mat);
  const Imprint im = imprint(grid, grid, m, n_mat);
  for (index_t c = 0; c < grid.n_cells(); ++c) {
    const double v = im.cell_volume[static_cast<std::size_t>(c)];
    ASSERT_GT(v, 0);
    for (int k = 0; k < n_mat; ++k) {
      const double want = k == m.raw()[static_cast<std::size_t>(c)] ? 1.0 : 0.0;
      EXPECT_NEAR(im.at(c, k) / v, want, 1e-12) << "cell " << c << " material " << k;
    }
  }
}

TEST(Imprint, SelfImprintIsPure2D) {
  expect_pure_self_imprint(quads(7, 5));
  io::MeshData d = quads(7, 5);
  jitter(d, 0.2, 1);
  transform(d, rotation(0.3, Vec3::UnitZ()), Vec3(1, 2, 0));
  expect_pure_self_imprint(d);
}

TEST(Imprint, SelfImprintIsPure3D) {
  expect_pure_self_imprint(hexes(4, 3, 3));
  io::MeshData d = hexes(4, 3, 3);
  jitter(d, 0.2, 2);  // non-planar faces
  transform(d, rotation(0.4, Vec3(1, 2, 3)), Vec3(-1, 0.5, 2));
  expect_pure_self_imprint(d);
}

// Each output cell its own material: the imprinted volumes of a cell sum to its volume
// when the input grid covers it.
void expect_cell_sums(const io::MeshData& input, const io::MeshData& output) {
  CellMaterials own(static_cast<std::size_t>(output.n_cells()));
  for (CellId o : id_range<CellId>(output.n_cells())) own[o] = o.value();
  const Imprint im = imprint(input, output, own, output.n_cells());
  for (index_t o = 0; o < output.n_cells(); ++o) {
    double s = 0;
    for (index_t c = 0; c < input.n_cells(); ++c) s += im.at(c, o);
    const double v = im.output_volume[static_cast<std::size_t>(o)];
    EXPECT_GT(v, 0);
    EXPECT_NEAR(s, v, 1e-12 * std::max(1.0, v)) << "output cell " << o;
  }
}

TEST(Imprint, OutputCellVolumesAreCovered2D) {
  io::MeshData in = quads(8, 8, 1.0, 1.0);
  jitter(in, 0.15, 3);
  io::MeshData out = quads(5, 4, 0.9, 1.1);
  jitter(out, 0.2, 4);
  transform(out, rotation(0.5, Vec3::UnitZ()), Vec3(3, 1.5, 0));
  expect_cell_sums(in, out);
}

TEST(Imprint, OutputCellVolumesAreCovered3D) {
  io::MeshData in = hexes(6, 6, 6);
  jitter(in, 0.15, 5);
  io::MeshData out = hexes(3, 2, 3, 0.9);
  jitter(out, 0.15, 6);
  transform(out, Eigen::Matrix3d::Identity(), Vec3(-1.35, -0.9, -1.35));  // centred
  transform(out, rotation(0.6, Vec3(1, 1, 0)), Vec3(3, 3, 3));
  expect_cell_sums(in, out);
}

TEST(Imprint, VolumePerMaterialIsConserved) {
  io::MeshData in = hexes(5, 5, 4);
  jitter(in, 0.2, 7);
  io::MeshData out = hexes(5, 5, 4);  // the same domain's boundary, other interior nodes
  jitter(out, 0.2, 8);
  const io::MeshData flat = hexes(5, 5, 4);
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    const Vec3 p = flat.points[i];
    const bool boundary =
        p.x() == 0 || p.x() == 5 || p.y() == 0 || p.y() == 5 || p.z() == 0 || p.z() == 4;
    if (boundary) in.points[i] = out.points[i] = p;  // flat boundary shared by both meshes
  }
  const CellMaterials m = pattern(out.n_cells(), 4);
  const Imprint im = imprint(in, out, m, 4);
  for (int k = 0; k < 4; ++k) {
    double s = 0;
    for (index_t c = 0; c < in.n_cells(); ++c) s += im.at(c, k);
    EXPECT_NEAR(s, im.output_volume[static_cast<std::size_t>(k)], 1e-11) << "material " << k;
  }
  EXPECT_NEAR(total(im.cell_volume), 100.0, 1e-11);
  EXPECT_NEAR(total(im.output_volume), 100.0, 1e-11);
}

TEST(Imprint, ThreadCountDoesNotChangeTheResult) {
  io::MeshData in = hexes(6, 5, 4);
  jitter(in, 0.2, 9);
  io::MeshData out = hexes(6, 5, 4);
  jitter(out, 0.25, 10);
  transform(out, rotation(0.05, Vec3(0, 0, 1)), Vec3(0.1, 0, 0));
  const CellMaterials m = pattern(out.n_cells(), 3);
  set_threads(1);
  const Imprint a = imprint(in, out, m, 3);
  set_threads(2);
  const Imprint b = imprint(in, out, m, 3);
  set_threads(0);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.cell_volume, b.cell_volume);
}

TEST(Imprint, DartShapedInputCell) {
  // The centre node of a 2x2 grid pulled towards a corner: two of the cells are darts.
  io::MeshData in = quads(2, 2);
  in.points[4] = Vec3(0.3, 0.3, 0);
  expect_pure_self_imprint(in);
  expect_cell_sums(in, quads(4, 4, 0.5, 0.5));
  const Imprint im = imprint(in, quads(1, 1, 2, 2), materials({0}), 1);
  for (index_t c = 0; c < 4; ++c)
    EXPECT_NEAR(im.at(c, 0), im.cell_volume[static_cast<std::size_t>(c)], 1e-14);
}

// --- Monte-Carlo checks --------------------------------------------------------------

// Point in a convex straight-edged quad: on the left of (or on) each counter-clockwise edge.
bool in_quad(const io::MeshData& d, index_t c, const Vec3& p) {
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = d.points[d.cells[static_cast<std::size_t>(4 * c + k)].idx()];
    const Vec3& b = d.points[d.cells[static_cast<std::size_t>(4 * c + (k + 1) % 4)].idx()];
    if ((b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()) < 0) return false;
  }
  return true;
}

// Parallelepiped cells: the trilinear map is affine, inverted from corner 0's edges.
bool in_parallelepiped(const io::MeshData& d, index_t c, const Vec3& p) {
  auto at = [&](int k) { return d.points[d.cells[static_cast<std::size_t>(8 * c + k)].idx()]; };
  Eigen::Matrix3d a;
  a.col(0) = at(1) - at(0);
  a.col(1) = at(2) - at(0);
  a.col(2) = at(4) - at(0);
  const Vec3 t = a.lu().solve(p - at(0));
  return t.minCoeff() >= 0 && t.maxCoeff() <= 1;
}

template <class InCell>
void expect_monte_carlo(const io::MeshData& in, const io::MeshData& out, InCell in_cell,
                        const Eigen::AlignedBox3d& box, int samples) {
  const int n_mat = 2;
  const CellMaterials m = pattern(out.n_cells(), n_mat);
  const Imprint im = imprint(in, out, m, n_mat);
  std::vector<double> hits(im.volume.size(), 0.0);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0, 1);
  for (int s = 0; s < samples; ++s) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = box.min()[a] + u(rng) * box.sizes()[a];
    if (in.dim == 2) p.z() = 0;
    index_t ci = -1, co = -1;
    for (index_t c = 0; c < in.n_cells() && ci < 0; ++c)
      if (in_cell(in, c, p)) ci = c;
    for (index_t o = 0; o < out.n_cells() && co < 0; ++o)
      if (in_cell(out, o, p)) co = o;
    if (ci >= 0 && co >= 0)
      hits[static_cast<std::size_t>(ci * n_mat + m.raw()[static_cast<std::size_t>(co)])] += 1;
  }
  const double w = box.sizes().head(in.dim).prod() / samples;
  double err = 0, sum = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const double p = hits[i] / samples;
    const double sigma =
        std::sqrt(std::max(p * (1 - p), 1.0 / samples) / samples) * box.sizes().head(in.dim).prod();
    EXPECT_NEAR(im.volume[i], hits[i] * w, 5 * sigma + 1e-12) << "slot " << i;
    err += std::abs(im.volume[i] - hits[i] * w);
    sum += im.volume[i];
  }
  EXPECT_GT(sum, 0.2 * box.sizes().head(in.dim).prod());  // the meshes do overlap
  EXPECT_LT(err / sum, 0.05);
}

TEST(Imprint, MatchesMonteCarlo2D) {
  io::MeshData in = quads(6, 5);
  jitter(in, 0.2, 11);
  io::MeshData out = quads(5, 5, 1.1, 0.9);
  jitter(out, 0.2, 12);
  transform(out, rotation(0.35, Vec3::UnitZ()), Vec3(1.5, -0.5, 0));
  expect_monte_carlo(in, out, in_quad, Eigen::AlignedBox3d(Vec3(-0.5, -1, 0), Vec3(6.5, 6, 0)),
                     60000);
}

TEST(Imprint, MatchesMonteCarlo3D) {
  io::MeshData in = hexes(4, 4, 3);
  io::MeshData out = hexes(3, 3, 3, 1.1);
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 1) = 0.3;
  shear(2, 0) = -0.2;
  transform(out, rotation(0.5, Vec3(1, 2, 2)) * shear, Vec3(0.7, 0.2, -0.3));
  expect_monte_carlo(in, out, in_parallelepiped,
                     Eigen::AlignedBox3d(Vec3(-0.2, -0.2, -0.2), Vec3(4.2, 4.2, 3.2)), 40000);
}

// A unit cube whose top corner (1, 1, 1), node 7, moves to height h: the top face folds
// along its diagonal from node 4 (the lowest id) to node 7, a valley for h < 1 and a ridge
// for h > 1. Its volume is the mean height of the two top triangles, (2 + h) / 3. Layers
// of an output column of height 0.5 each (materials 0, 1, 2) get exact known shares.
void expect_folded_cube(double h, const std::array<double, 3>& want) {
  io::MeshData in = hexes(1, 1, 1);
  ASSERT_EQ(in.points[7], Vec3(1, 1, 1));
  in.points[7].z() = h;
  const io::MeshData out = io::from_mesh(make_hex_grid(1, 1, 3, Vec3::Zero(), Vec3(1, 1, 0.5)));
  const Imprint im = imprint(in, out, materials({0, 1, 2}), 3);
  EXPECT_NEAR(im.cell_volume[0], (2 + h) / 3, 1e-14);
  for (int m = 0; m < 3; ++m)
    EXPECT_NEAR(im.at(0, m), want[static_cast<std::size_t>(m)], 1e-14) << "material " << m;
}

TEST(Imprint, CubeWithAValleyFace) {
  expect_folded_cube(0.8, {0.5, 2.8 / 3 - 0.5, 0});
}

TEST(Imprint, CubeWithARidgeFace) {
  expect_folded_cube(1.2, {0.5, 0.5, 3.2 / 3 - 1});
}

// An output that is the input moved by a tiny amount (as smoothing leaves an adapted mesh):
// nearly coincident faces everywhere, where clipping must neither lose nor double volume.
TEST(Imprint, NearlyCoincidentMeshesConserveVolume) {
  const io::MeshData flat = hexes(6, 5, 4);
  io::MeshData in = flat;
  jitter(in, 0.2, 21);
  io::MeshData out = in;
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (std::size_t i = 0; i < flat.points.size(); ++i) {
    const Vec3& p = flat.points[i];
    const bool boundary =
        p.x() == 0 || p.x() == 6 || p.y() == 0 || p.y() == 5 || p.z() == 0 || p.z() == 4;
    if (boundary)
      in.points[i] = out.points[i] = p;  // both cover the same box
    else if (rng() % 2)
      out.points[i] += Vec3(u(rng), u(rng), u(rng));
  }
  const CellMaterials m = pattern(out.n_cells(), 3);
  const Imprint im = imprint(in, out, m, 3);
  for (int k = 0; k < 3; ++k) {
    double s = 0;
    for (index_t c = 0; c < in.n_cells(); ++c) s += im.at(c, k);
    EXPECT_NEAR(s, im.output_volume[static_cast<std::size_t>(k)], 1e-12) << "material " << k;
  }
  for (index_t c = 0; c < in.n_cells(); ++c) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += im.at(c, k);
    EXPECT_NEAR(s, im.cell_volume[static_cast<std::size_t>(c)], 1e-12) << "cell " << c;
  }
}

// --- Known answer ----------------------------------------------------------------------

// Input fractions of a straight interface x' = a (x' along the rotated x axis) and an
// output whose interface is the grid line x' = b: each material is off by |a - b| * height,
// in the input cells between the two lines.
template <class Make>
void expect_line_discrepancy(Make make, int dim) {
  const int n = 10;
  const double a = 3.37, b = 6.0, h = 1.0;
  io::MeshData in = make(n, h), out = make(n / 2, 2 * h);
  const Eigen::Matrix3d r = dim == 3 ? rotation(0.7, Vec3(1, -2, 3)) : rotation(0.7, Vec3::UnitZ());
  transform(in, r, Vec3(1, 2, 3 * (dim - 2)));
  transform(out, r, Vec3(1, 2, 3 * (dim - 2)));
  Fractions f(in.n_cells(), {"vf_left", "vf_right"});
  const io::MeshData flat = make(n, h);
  for (CellId c : id_range<CellId>(in.n_cells())) {
    const double x0 =
        flat.points[flat.cells[c.idx() * static_cast<std::size_t>(flat.nodes_per_cell())].idx()]
            .x();
    const double left = std::clamp((a - x0) / h, 0.0, 1.0);
    f(c, 0) = left;
    f(c, 1) = 1 - left;
  }
  CellMaterials m(static_cast<std::size_t>(out.n_cells()));
  const io::MeshData fo = make(n / 2, 2 * h);
  for (index_t o = 0; o < out.n_cells(); ++o) {
    m.raw()[static_cast<std::size_t>(o)] =
        fo.points[fo.cells[static_cast<std::size_t>(o) *
                           static_cast<std::size_t>(fo.nodes_per_cell())]
                      .idx()]
                    .x() < b
            ? 0
            : 1;
  }
  const DiscrepancyReport d = discrepancy(imprint(in, out, m, 2), f);
  const double height = std::pow(n * h, dim - 1);
  EXPECT_NEAR(d.total, 2 * (b - a) * height, 1e-10);
  EXPECT_NEAR(d.relative, 2 * (b - a) * height / std::pow(n * h, dim), 1e-12);
  // Per cell: the column of cells with x in [3, 4) loses 2 * 0.63, those in [4, 6) 2 * 1.
  const double per = std::pow(h, dim - 1);
  for (CellId c : id_range<CellId>(in.n_cells())) {
    const double x0 =
        flat.points[flat.cells[c.idx() * static_cast<std::size_t>(flat.nodes_per_cell())].idx()]
            .x();
    const double want = x0 == 3 ? 2 * (4 - a) * per : (x0 == 4 || x0 == 5) ? 2 * per : 0.0;
    EXPECT_NEAR(d.per_cell[c.idx()], want, 1e-12) << "cell " << c.value();
  }
  EXPECT_NEAR(d.max_cell, 2 * per, 1e-12);
  EXPECT_NEAR(d.materials[0].input, a * height, 1e-10);
  EXPECT_NEAR(d.materials[0].output, b * height, 1e-10);
  EXPECT_NEAR(d.materials[0].imprinted, b * height, 1e-10);
}

TEST(Discrepancy, StraightInterfaceAtKnownOffset2D) {
  expect_line_discrepancy([](int n, double h) { return quads(n, n, h, h); }, 2);
}

TEST(Discrepancy, StraightInterfaceAtKnownOffset3D) {
  expect_line_discrepancy([](int n, double h) { return hexes(n, n, n, h); }, 3);
}

TEST(Discrepancy, RejectsMismatchedFractions) {
  const io::MeshData g = quads(2, 2);
  const Imprint im = imprint(g, g, materials({0, 1, 0, 1}), 2);
  EXPECT_THROW(discrepancy(im, Fractions(4, {"vf_a"})), InputError);
  EXPECT_THROW(imprint(g, g, materials({0, 2, 0, 1}), 2), InputError);
  EXPECT_THROW(imprint(g, hexes(1, 1, 1), materials({0}), 1), InputError);
  io::MeshData broken = g;
  broken.cells[5] = NodeId(9);
  EXPECT_THROW(imprint(broken, g, materials({0, 1, 0, 1}), 2), InputError);
}

// Fractions: a fills cells 0 and 1, b cells 2 and 3, c nothing; the output gives cell 2 to a.
// Volume errors (output - input) / input: a +1/2, b -1/2, c undefined (no input volume).
TEST(Discrepancy, VolumeErrorPerMaterial) {
  const io::MeshData g = quads(2, 2, 0.5, 0.5);
  Fractions f(4, {"a", "b", "c"});
  for (CellId c : id_range<CellId>(4)) f(c, c.value() < 2 ? 0 : 1) = 1;
  const Imprint im = imprint(g, g, materials({0, 0, 0, 1}), 3);
  DiscrepancyOptions o;
  const DiscrepancyReport open = discrepancy(im, f, o);
  EXPECT_NEAR(open.materials[0].volume_error(), 0.5, 1e-12);
  EXPECT_NEAR(open.materials[1].volume_error(), -0.5, 1e-12);
  EXPECT_TRUE(std::isnan(open.materials[2].volume_error()));
  EXPECT_EQ(open.worst_material, 0);  // ties go to the lowest index
  EXPECT_TRUE(open.passed());         // no bound
  o.max_volume_error = 0.5 + 1e-9;
  EXPECT_TRUE(discrepancy(im, f, o).passed());
  o.max_volume_error = 0.49;
  EXPECT_FALSE(discrepancy(im, f, o).passed());
  o.max_volume_error = -1;
  EXPECT_THROW(discrepancy(im, f, o), OptionError);
  // Nothing has input volume: no worst material, nothing to fail.
  EXPECT_EQ(discrepancy(im, Fractions(4, {"a", "b", "c"}), {}).worst_material, -1);
}

// A jittered 3x3x3 output over a 3x3x3 grid with fractions, at 1e-300 (volumes 1e-900, below
// the smallest double) and 1e300 (volumes overflow): the imprint runs in the grid's UnitFrame,
// so the relative figures are those at unit scale, and the volumes it reports go back to the
// grid's units (0 and infinity there: not representable); quality and mesh check as well.
TEST(Discrepancy, TheSameFiguresAtAnyUnit) {
  const io::MeshData grid = hexes(3, 3, 3);
  io::MeshData out = hexes(3, 3, 3);
  jitter(out, 0.2, 7, false);
  for (std::size_t i = 0; i < out.points.size(); ++i)  // the domain stays the same box
    for (int a = 0; a < 3; ++a)
      if (grid.points[i][a] == 0 || grid.points[i][a] == 3) out.points[i][a] = grid.points[i][a];
  Fractions f(grid.n_cells(), {"a", "b"});
  for (CellId c : id_range<CellId>(grid.n_cells())) {
    const double x = 0.1 + 0.8 * double(c.value() % 5) / 4;
    f(c, 0) = x;
    f(c, 1) = 1 - x;
  }
  const CellMaterials m = pattern(out.n_cells(), 2);
  const DiscrepancyReport base = discrepancy(imprint(grid, out, m, 2), f);
  const QualityReport q = quality_report(out);
  ASSERT_TRUE(q.check_ok());
  for (double s : {1e-300, 1e-6, 1e300}) {
    io::MeshData g = grid, o = out;
    transform(g, Eigen::Matrix3d::Identity() * s, Vec3::Zero());
    transform(o, Eigen::Matrix3d::Identity() * s, Vec3::Zero());
    const DiscrepancyReport d = discrepancy(imprint(g, o, m, 2), f);
    EXPECT_NEAR(d.relative, base.relative, 1e-12) << s;
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(d.materials[static_cast<std::size_t>(k)].volume_error(),
                  base.materials[static_cast<std::size_t>(k)].volume_error(), 1e-12)
          << s;
    const double volume = d.in_grid_units(d.input_volume), want = s * s * s * 27;
    if (want > 0 && std::isfinite(want))
      EXPECT_NEAR(volume / want, 1.0, 1e-12) << s;
    else
      EXPECT_EQ(volume, want) << s;  // 0 or infinity: not representable
    const QualityReport r = quality_report(o);
    EXPECT_NEAR(r.scaled_jacobian.min, q.scaled_jacobian.min, 1e-12) << s;
    EXPECT_NEAR(r.shape.min, q.shape.min, 1e-12) << s;
    EXPECT_TRUE(r.check_ok()) << s;
    EXPECT_EQ(r.check.inverted_cells, 0) << s;
  }
}

TEST(TargetDistances, SumAndMax) {
  io::MeshData d = quads(1, 1);
  EXPECT_FALSE(target_distances(d).has_targets);
  io::DataArray t;
  t.name = "target";
  t.n_components = 3;
  const double nan = std::nan("");
  t.values = {0, 0, 0, 1, 0.5, 0, nan, nan, nan, 1, 6, 0};  // nodes (0,0) (1,0) (0,1) (1,1)
  d.set_point_array(t);
  const TargetDistances r = target_distances(d);
  EXPECT_TRUE(r.has_targets);
  EXPECT_EQ(r.nodes, 3);
  EXPECT_DOUBLE_EQ(r.sum, 0.5 + 5.0);
  EXPECT_DOUBLE_EQ(r.max, 5.0);
  EXPECT_EQ(r.max_node, NodeId(3));
  t.n_components = 1;
  t.values.resize(4);
  d.set_point_array(t);
  EXPECT_THROW(target_distances(d), InputError);
}

}  // namespace
}  // namespace hexadapt
