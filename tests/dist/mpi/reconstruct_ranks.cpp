// Reconstruction spread over the ranks of an MPI job (run under mpirun -np N): every rank
// reconstructs its slab of a grid with the ghost layers greedy_ghost_layers asks for, and the
// owned pixels gathered in rank order and the figures must be those of one rank
// reconstructing the whole grid, to the bit.
#include <gtest/gtest.h>

#include "../../assign/assign_test_cases.h"
#include "hexadapt/reconstruct/pixel_mesh.h"
#include "hexadapt/reconstruct/pixel_output.h"
#include "hexadapt/reconstruct/reconstruct.h"
#include "slab_case.h"

namespace hexadapt {
namespace {

using reconstruct::Reconstruction;
using reconstruct::ReconstructOptions;

/// Every rank's piece of a pixel mesh (no point shared), concatenated in rank order.
io::MeshData gathered(const io::MeshData& piece) {
  const dist::Communicator& comm = test::world();
  std::vector<double> xyz;
  for (const Vec3& p : piece.points) xyz.insert(xyz.end(), p.data(), p.data() + 3);
  std::vector<std::int64_t> cells;
  for (NodeId n : piece.cells) cells.push_back(n.value());
  const std::vector<std::int64_t> counts = dist::all_gather_values(
      comm, std::vector<std::int64_t>{static_cast<std::int64_t>(piece.points.size())});
  std::int64_t shift = 0;
  for (int r = 0; r < comm.rank(); ++r) shift += counts[static_cast<std::size_t>(r)];
  for (std::int64_t& n : cells) n += shift;
  io::MeshData whole;
  const std::vector<double> all_xyz = dist::all_gather_values(comm, xyz);
  for (std::size_t i = 0; i + 2 < all_xyz.size(); i += 3)
    whole.points.emplace_back(all_xyz[i], all_xyz[i + 1], all_xyz[i + 2]);
  for (std::int64_t n : dist::all_gather_values(comm, cells))
    whole.cells.push_back(NodeId(static_cast<index_t>(n)));
  for (const io::DataArray& a : piece.cell_data) {
    io::DataArray w = a;
    w.values = dist::all_gather_values(comm, a.values);
    whole.cell_data.push_back(std::move(w));
  }
  return whole;
}

/// The reconstruction of the slab this rank holds with `ghost_layers` layers of ghost cells.
template <class M>
Reconstruction on_ranks(const M& whole, const Fractions& fractions, const CellMaterials& material,
                        const std::array<int, 3>& cells, const ReconstructOptions& options,
                        int ghost_layers, dist::Block* block,
                        const std::vector<double>& layer_weights = {}) {
  const int rank = test::world().rank(), size = test::world().size();
  const dist::Slab slab =
      layer_weights.empty()
          ? dist::structured_slab(cells, M::dim, rank, size, ghost_layers)
          : dist::weighted_slab(cells, M::dim, rank, size, ghost_layers, layer_weights);
  const auto [mesh, part] = test::held_part(whole, fractions, cells, slab);
  CellMaterials held(static_cast<std::size_t>(slab.block.held_cells));
  for (CellId c : id_range<CellId>(slab.block.held_cells))
    held[c] = material[CellId(static_cast<index_t>(slab.block.global(c)))];
  *block = slab.block;
  return reconstruct::reconstruct(mesh, part, held, options, {test::world(), slab.block});
}

template <class M>
int ghost_layers_for(const ReconstructOptions& options) {
  const int nsub = options.pixels.nsub ? options.pixels.nsub : reconstruct::default_nsub(M::dim);
  return reconstruct::greedy_ghost_layers(nsub, options.greedy);
}

template <class M>
void expect_same_as_one_rank(const M& whole, const Fractions& fractions,
                             const std::array<int, 3>& cells, ReconstructOptions options,
                             const std::vector<double>& layer_weights = {}) {
  options.extract_model = false;
  const CellMaterials material = majority_materials(fractions);
  const Reconstruction one = reconstruct::reconstruct(whole, fractions, material, options);
  ASSERT_GT(one.result.plan.n_free_blocks, 0);
  dist::Block block;
  const Reconstruction r = on_ranks(whole, fractions, material, cells, options,
                                    ghost_layers_for<M>(options), &block, layer_weights);

  const io::MeshData serial = reconstruct::pixel_mesh_data(one.pixels);
  const io::MeshData all = gathered(reconstruct::pixel_mesh_data(r.pixels, block));
  ASSERT_EQ(all.cell_data.size(), serial.cell_data.size());
  for (std::size_t a = 0; a < all.cell_data.size(); ++a) {
    const auto& got = all.cell_data[a].values;
    const auto& want = serial.cell_data[a].values;
    ASSERT_EQ(got.size(), want.size()) << all.cell_data[a].name;
    std::size_t differ = 0;
    for (std::size_t i = 0; i < got.size(); ++i) differ += got[i] != want[i] ? 1 : 0;
    EXPECT_EQ(differ, 0u) << "pixels whose " << all.cell_data[a].name << " differs from one rank's";
  }
  EXPECT_EQ(all.points, serial.points);
  EXPECT_EQ(all.cells, serial.cells);

  const reconstruct::ReconstructResult &a = r.result, &b = one.result;
  EXPECT_EQ(a.greedy.rounds, b.greedy.rounds);
  EXPECT_EQ(a.greedy.fallback_pixels, b.greedy.fallback_pixels);
  EXPECT_EQ(a.edgecut, b.edgecut);
  EXPECT_EQ(a.discrepancy, b.discrepancy);  // exact sums: the same bits
  EXPECT_EQ(a.unpixelated_discrepancy, b.unpixelated_discrepancy);
  EXPECT_EQ(a.domain_volume, b.domain_volume);
  EXPECT_EQ(a.relative_discrepancy, b.relative_discrepancy);
  EXPECT_EQ(a.plan.n_blocks, b.plan.n_blocks);
  EXPECT_EQ(a.plan.n_free_blocks, b.plan.n_free_blocks);
  EXPECT_EQ(a.plan.n_pixels, b.plan.n_pixels);
  EXPECT_EQ(a.plan.n_free_pixels, b.plan.n_free_pixels);
  EXPECT_EQ(a.plan.bytes, b.plan.bytes);
}

// Three balls crossing every rank border of a grid of many cell shapes.
Fractions three_balls(const HexMesh& mesh) {
  return test::ball_fractions(
      mesh, {{Vec3(3.2, 3.1, 2.9), 2.6}, {Vec3(5.5, 4.4, 6.3), 2.9}, {Vec3(4.1, 4.3, 9.4), 2.2}});
}

ReconstructOptions with_nsub(int nsub, int sweeps = 3) {
  ReconstructOptions o;
  o.pixels.nsub = nsub;
  o.greedy.diffusion_sweeps = sweeps;
  return o;
}

TEST(ReconstructOnRanks, BallsInAHexGridAsOnOneRank) {
  const std::array<int, 3> cells{9, 8, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 7);
  const Fractions f = three_balls(mesh);
  for (const auto& options : {with_nsub(0), with_nsub(1), with_nsub(2), with_nsub(2, 5)}) {
    SCOPED_TRACE("nsub " + std::to_string(options.pixels.nsub) + ", sweeps " +
                 std::to_string(options.greedy.diffusion_sweeps));
    expect_same_as_one_rank(mesh, f, cells, options);
  }
}

TEST(ReconstructOnRanks, NoisyQuadFractionsAsOnOneRank) {
  const std::array<int, 3> cells{23, 17, 1};
  const auto mesh = test::jittered_grid<QuadMesh>(cells, 5);
  const Fractions f = test::random_fractions(mesh.n_cells(), 4, 3, 2);
  for (int nsub : {0, 1, 2}) expect_same_as_one_rank(mesh, f, cells, with_nsub(nsub));
}

// Cells of 1/8 far from the origin: each slab alone would have another frame.
TEST(ReconstructOnRanks, AGridFarFromTheOriginAsOnOneRank) {
  const std::array<int, 3> cells{9, 8, 12};
  const auto jittered = test::jittered_grid<HexMesh>(cells, 7);
  const Fractions f = three_balls(jittered);
  std::vector<Vec3> points;
  for (NodeId n : id_range<NodeId>(jittered.n_nodes()))
    points.push_back(jittered.point(n) * 0.125 + Vec3(1e6, -3e5, 7e5));
  expect_same_as_one_rank(make_hex_grid(cells[0], cells[1], cells[2], std::move(points)), f, cells,
                          with_nsub(0));
}

// Mixed cells only in the top layers: the lower ranks have no free pixel, some no pixel.
TEST(ReconstructOnRanks, RanksWithoutMixedCellsAsOnOneRank) {
  const std::array<int, 3> cells{6, 5, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 2);
  const Fractions f = test::ball_fractions(mesh, {{Vec3(3, 2.5, 12), 1.8}});
  expect_same_as_one_rank(mesh, f, cells, with_nsub(2));
}

// The tool's cut: every layer weighed by its cells' pixel bytes from slabs of equal layer
// counts with one ghost layer, then slabs of equal weights. The weights are those of the
// whole grid on one rank, to the bit, and the pixels those of one rank.
TEST(ReconstructOnRanks, ACutByPixelBytesAsOnOneRank) {
  const std::array<int, 3> cells{6, 5, 16};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 2);
  const Fractions f = test::ball_fractions(mesh, {{Vec3(3, 2.5, 11), 2.1}});
  const CellMaterials material = majority_materials(f);
  const ReconstructOptions options = with_nsub(2);
  const dist::Slab probe =
      dist::structured_slab(cells, 3, test::world().rank(), test::world().size(), 1);
  const auto [held, part] = test::held_part(mesh, f, cells, probe);
  CellMaterials held_material(static_cast<std::size_t>(probe.block.held_cells));
  for (CellId c : id_range<CellId>(probe.block.held_cells))
    held_material[c] = material[CellId(static_cast<index_t>(probe.block.global(c)))];
  const std::vector<double> weights = dist::layer_sums(
      test::world(), probe,
      reconstruct::owned_cell_bytes(held, part, held_material, options.pixels, probe.block));

  const dist::Slab whole = dist::structured_slab(cells, 3, 0, 1, 0);
  const std::vector<double> serial = dist::layer_sums(
      dist::serial(), whole,
      reconstruct::owned_cell_bytes(mesh, f, material, options.pixels, whole.block));
  EXPECT_EQ(weights, serial);
  EXPECT_GT(weights[11], 10 * weights[0]);  // the ball's layers weigh the most
  expect_same_as_one_rank(mesh, f, cells, options, weights);
}

// One ghost layer is too few (a pure cell's pixels depend on its neighbours' neighbours):
// a rank's own pixels come out otherwise than on one rank.
TEST(ReconstructOnRanks, OneGhostLayerGivesOtherPixels) {
  if (test::world().size() == 1) GTEST_SKIP() << "one rank has no ghost";
  const std::array<int, 3> cells{9, 8, 12};
  const auto mesh = test::jittered_grid<HexMesh>(cells, 7);
  const Fractions f = test::random_fractions(mesh.n_cells(), 3, 3, 11);
  ReconstructOptions options = with_nsub(2, 5);
  options.extract_model = false;
  const CellMaterials material = majority_materials(f);
  const Reconstruction one = reconstruct::reconstruct(mesh, f, material, options);
  dist::Block block;
  const Reconstruction r = on_ranks(mesh, f, material, cells, options, 1, &block);
  const io::MeshData all = gathered(reconstruct::pixel_mesh_data(r.pixels, block));
  const io::MeshData serial = reconstruct::pixel_mesh_data(one.pixels);
  ASSERT_EQ(all.cell_data[0].values.size(), serial.cell_data[0].values.size());
  EXPECT_NE(all.cell_data[0].values, serial.cell_data[0].values);
  expect_same_as_one_rank(mesh, f, cells, options);  // with greedy_ghost_layers: the same
}

TEST(ReconstructOnRanks, OtherMethodsAndTheModelAreRefusedOnSeveralRanks) {
  if (test::world().size() == 1) GTEST_SKIP() << "one rank runs every method";
  const std::array<int, 3> cells{4, 4, 6};
  const HexMesh mesh = make_hex_grid(cells[0], cells[1], cells[2]);
  const Fractions f = test::ball_fractions(mesh, {{Vec3(2, 2, 3), 1.5}});
  ReconstructOptions annealing;
  annealing.extract_model = false;
  annealing.method = reconstruct::Method::annealing;
  const ReconstructOptions model;
  dist::Block block;
  for (const ReconstructOptions& o : {annealing, model})
    EXPECT_THROW(on_ranks(mesh, f, majority_materials(f), cells, o, 2, &block), OptionError);
}

}  // namespace
}  // namespace hexadapt
