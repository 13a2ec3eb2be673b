// adapt spread over the ranks of an MPI job (run under mpirun -np N): every rank adapts its part
// of a generated case, a structured grid's slab or the cells PT-Scotch gives it, with the ghost
// layers around it. The parts must keep the guarantee at the cuts, fit together face to face
// into one conformal mesh, and come out the same at every run.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "../../adapt/generated_case.h"
#include "hexadapt/adapt/adapt_on_ranks.h"
#include "hexadapt/dist/dual_graph.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/dist/scotch_partition.h"
#include "hexadapt/io/mesh_part.h"
#include "slab_case.h"

namespace hexadapt {
namespace {

using Point = std::array<double, 3>;
using Face = std::vector<Point>;  // corners, sorted

// Every rank's part's cells as their corner points, in rank order.
template <class M>
std::vector<std::vector<Point>> gathered_cells(const AnyAdaptResult& part) {
  const auto& r = std::get<AdaptResult<M>>(part);
  std::vector<double> mine;
  for (CellId c : id_range<CellId>(r.mesh.n_cells()))
    for (NodeId v : r.mesh.cell_nodes(c)) {
      const Vec3 p = r.mesh.point(v);  // a quad mesh's point is a copy
      mine.insert(mine.end(), {p.x(), p.y(), p.z()});
    }
  const std::vector<double> all = dist::all_gather_values(test::world(), mine);
  std::vector<std::vector<Point>> cells;
  constexpr std::size_t per_cell = 3 * M::nodes_per_cell;
  for (std::size_t k = 0; k + per_cell <= all.size(); k += per_cell) {
    std::vector<Point> cell;
    for (std::size_t i = k; i < k + per_cell; i += 3) cell.push_back({all[i], all[i + 1], all[i + 2]});
    cells.push_back(cell);
  }
  return cells;
}

// The faces of the gathered cells, each with the number of cells around it: in one conformal
// mesh an inner face has two, a face on the grid's boundary (`low`, `high`: its box) one.
template <class M>
void expect_conformal(const std::vector<std::vector<Point>>& cells, const Point& low,
                      const Point& high) {
  std::map<Face, int> faces;
  for (const std::vector<Point>& cell : cells)
    for (std::size_t lf = 0; lf < static_cast<std::size_t>(M::faces_per_cell); ++lf) {
      Face f;
      const auto& corners = M::dim == 3 ? std::vector<int>(ref_hex::face_nodes[lf].begin(),
                                                           ref_hex::face_nodes[lf].end())
                                        : std::vector<int>(ref_quad::face_nodes[lf % 4].begin(),
                                                           ref_quad::face_nodes[lf % 4].end());
      for (int v : corners) f.push_back(cell[static_cast<std::size_t>(v)]);
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  const auto on_boundary = [&](const Face& f) {
    for (std::size_t a = 0; a < static_cast<std::size_t>(M::dim); ++a)
      for (double side : {low[a], high[a]})
        if (std::all_of(f.begin(), f.end(),
                        [&](const Point& p) { return std::abs(p[a] - side) < 1e-9; }))
          return true;
    return false;
  };
  int open = 0, crowded = 0;
  for (const auto& [f, n] : faces) {
    open += n == 1 && !on_boundary(f);
    crowded += n > 2;
  }
  EXPECT_EQ(open, 0) << "faces inside the grid with a cell on one side only";
  EXPECT_EQ(crowded, 0) << "faces shared by more than two cells";
}

// The box of a grid's points.
template <class M>
std::pair<Point, Point> box(const M& grid) {
  Vec3 lo = grid.point(NodeId(0)), hi = lo;
  for (NodeId v : id_range<NodeId>(grid.n_nodes())) {
    lo = lo.cwiseMin(grid.point(v));
    hi = hi.cwiseMax(grid.point(v));
  }
  return {{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}};
}

// The assigned grid of the cells `block` names, `mesh` holding them.
template <class M>
AssignedGrid held_grid(M mesh, const Fractions& fractions, const CellMaterials& material,
                       const dist::Block& block) {
  AssignedGrid g;
  Fractions f(block.held_cells, fractions.names());
  for (CellId c : id_range<CellId>(block.held_cells)) {
    const CellId whole(static_cast<index_t>(block.global(c)));
    for (int m = 0; m < f.n_materials(); ++m) f(c, m) = fractions(whole, m);
    g.material.push_back(material[whole]);
  }
  g.mesh = std::move(mesh);
  g.fractions = std::move(f);
  return g;
}

// The run's checks: the guarantee over every rank's part, one conformal mesh, the same cells at
// a second run.
template <class M>
void expect_guaranteed(const std::function<RankAdaptResult()>& run, const M& whole,
                       const AdaptOptions& options) {
  const RankAdaptResult r = run();
  ASSERT_FALSE(r.stopped_bad_input);
  EXPECT_EQ(r.total.failing(), 0);
  EXPECT_GE(r.total.min_quality, options.threshold);
  const auto& part = std::get<AdaptResult<M>>(r.part);
  for (CellId c : id_range<CellId>(part.mesh.n_cells()))
    EXPECT_GE(part.mesh.cell_quality(c), options.threshold) << "cell " << c.value();
  const auto cells = gathered_cells<M>(r.part);
  EXPECT_EQ(static_cast<index_t>(cells.size()), r.total.cells);
  EXPECT_GE(r.total.cells, whole.n_cells());
  const auto [low, high] = box(whole);
  expect_conformal<M>(cells, low, high);
  EXPECT_GE(r.total.near_interface, r.total.interface_nodes * 9 / 10);
  EXPECT_EQ(gathered_cells<M>(run().part), cells) << "a second run gave other cells";
}

void on_slabs(const test::GeneratedCase& c) {
  test::with_generated_case(c, [&](const auto& whole, const Fractions& f, const CellMaterials& m) {
    using M = std::decay_t<decltype(whole)>;
    std::array<int, 3> cells{c.dims[0], c.dims[1], M::dim == 3 ? c.dims[2] : 1};
    const int layers = cells[M::dim - 1];
    const dist::Slab slab = dist::structured_slab(cells, M::dim, test::world().rank(),
                                                  test::world().size(), adapt_ghost_layers);
    const AdaptOptions options;
    expect_guaranteed<M>(
        [&] {
          auto [mesh, part] = test::held_part(whole, f, cells, slab);
          (void)part;
          return adapt(held_grid(std::move(mesh), f, m, slab.block), options,
                       {test::world(), slab.block}, SlabPlace{slab, layers});
        },
        whole, options);
  });
}

// This rank's share of the whole mesh's cells (contiguous, in rank order) as a part to cut.
template <class M>
io::MeshPart share_of(const M& whole) {
  const int rank = test::world().rank(), size = test::world().size();
  const std::int64_t first = std::int64_t{whole.n_cells()} * rank / size,
                     end = std::int64_t{whole.n_cells()} * (rank + 1) / size;
  io::MeshPart part;
  part.n_cells = whole.n_cells();
  part.n_nodes = whole.n_nodes();
  part.data.dim = M::dim;
  for (NodeId v : id_range<NodeId>(whole.n_nodes())) {
    part.node_ids.push_back(v.value());
    part.data.points.push_back(whole.point(v));
  }
  for (std::int64_t c = first; c < end; ++c) {
    part.cell_ids.push_back(c);
    for (NodeId v : whole.cell_nodes(CellId(static_cast<index_t>(c)))) part.data.cells.push_back(v);
  }
  return part;
}

void on_scotch_parts(const test::GeneratedCase& c) {
  test::with_generated_case(c, [&](const auto& whole, const Fractions& f, const CellMaterials& m) {
    using M = std::decay_t<decltype(whole)>;
    const auto& comm = dynamic_cast<const dist::MpiCommunicator&>(test::world());
    io::MeshPart part = share_of(whole);
    std::vector<std::int64_t> cell_nodes;
    for (const NodeId v : part.data.cells) cell_nodes.push_back(part.node_ids[v.idx()]);
    const std::vector<int> to = dist::scotch_partition(
        comm, dist::dual_graph(comm, M::nodes_per_cell, cell_nodes), comm.size());
    io::GhostedPart g =
        io::with_ghost_layers(comm, io::migrate(comm, std::move(part), to), adapt_ghost_layers);
    const dist::Block block =
        dist::Block::listed(g.part.cell_ids, g.owned_cells, g.part.node_ids, g.owns_node);
    const AdaptOptions options;
    expect_guaranteed<M>(
        [&] {
          M mesh = std::get<M>(io::to_mesh(g.part.data));
          return adapt(held_grid(std::move(mesh), f, m, block), options, {comm, block});
        },
        whole, options);
  });
}

TEST(AdaptOnRanks, AsteroidSlabsKeepTheGuaranteeAndMeet) {
  on_slabs({"asteroid", {12, 12, 14}});
}

TEST(AdaptOnRanks, JitteredAsteroidScotchPartsKeepTheGuaranteeAndMeet) {
  on_scotch_parts({"asteroid", {12, 12, 12}, -1, 0, 0.2});
}

TEST(AdaptOnRanks, DisksInQuadSlabsKeepTheGuaranteeAndMeet) {
  on_slabs({"venn", {24, 20}});
}

TEST(AdaptOnRanks, OtherMethodsAreRefusedOnEveryRank) {
  test::with_generated_case({"venn", {12, 12}}, [&](const auto& whole, const Fractions& f,
                                                   const CellMaterials& m) {
    const std::array<int, 3> cells{12, 12, 1};
    const dist::Slab slab = dist::structured_slab(cells, 2, test::world().rank(),
                                                  test::world().size(), adapt_ghost_layers);
    auto [mesh, part] = test::held_part(whole, f, cells, slab);
    (void)part;
    AdaptOptions options;
    options.method = AdaptMethod::base;
    const auto run = [&] {
      adapt(held_grid(std::move(mesh), f, m, slab.block), options, {test::world(), slab.block},
            SlabPlace{slab, 12});
    };
    try {
      run();
      ADD_FAILURE() << "the base method ran on ranks";
    } catch (const dist::CommonError& e) {
      EXPECT_EQ(e.rank(), 0);
      EXPECT_THROW(std::rethrow_exception(e.original()), OptionError);
    }
  });
}

}  // namespace
}  // namespace hexadapt
