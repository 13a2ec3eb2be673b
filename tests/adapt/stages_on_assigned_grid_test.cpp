// The stages' calls on the one value between them (AssignedGrid, as io::to_assigned_grid reads
// it) give what their calls on the typed mesh give, in 2D and 3D, and the stages that need a
// material per cell refuse a grid without one.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/assign/assign.h"
#include "hexadapt/core/error.h"
#include "hexadapt/generate/generate.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/mesh/unit_frame.h"
#include "hexadapt/reconstruct/reconstruct.h"

namespace hexadapt {
namespace {

// The generated case read as the assign stage reads its input: no material yet.
AssignedGrid generated_grid(const std::string& name, std::vector<int> dims) {
  generate::GenerateOptions o;
  o.case_name = name;
  o.dims = std::move(dims);
  io::AssignedGridOptions read;
  read.material = io::MaterialSource::none;
  return io::to_assigned_grid(generate::generate(o).data, read, name);
}

template <class M>
void expect_same_mesh(const M& a, const M& b) {
  ASSERT_EQ(a.n_nodes(), b.n_nodes());
  ASSERT_EQ(a.n_cells(), b.n_cells());
  for (NodeId v : id_range<NodeId>(a.n_nodes())) EXPECT_EQ(a.point(v), b.point(v));
  for (CellId c : id_range<CellId>(a.n_cells())) EXPECT_EQ(a.cell_nodes(c), b.cell_nodes(c));
}

void check_stages(AssignedGrid grid) {
  const assign::AssignResult a = assign::assign_materials(grid, {});
  std::visit(
      [&](const auto& mesh) {
        EXPECT_EQ(a.correction.labels.raw(),
                  assign::assign_materials(mesh, grid.fractions).correction.labels.raw());
      },
      grid.mesh);
  grid.material = a.correction.labels;

  reconstruct::ReconstructOptions ro;
  const reconstruct::Reconstruction r = reconstruct::reconstruct(grid, ro);
  const AdaptOptions ao;
  const AnyAdaptResult any = adapt(grid, ao, &r.model);
  std::visit(
      [&](const auto& mesh) {
        const reconstruct::Reconstruction typed =
            reconstruct::reconstruct(mesh, grid.fractions, grid.material, ro);
        EXPECT_EQ(r.result.plan.n_pixels, typed.result.plan.n_pixels);
        EXPECT_EQ(r.result.discrepancy, typed.result.discrepancy);
        EXPECT_EQ(r.model.points, typed.model.points);
        using M = std::decay_t<decltype(mesh)>;
        ASSERT_TRUE(std::holds_alternative<AdaptResult<M>>(any));
        const AdaptResult<M>& ours = std::get<AdaptResult<M>>(any);
        const AdaptResult<M> direct = adapt(mesh, grid.fractions, grid.material, ao, &typed.model);
        expect_same_mesh(ours.mesh, direct.mesh);
        EXPECT_EQ(ours.material.raw(), direct.material.raw());
        EXPECT_EQ(ours.n_near_interface, direct.n_near_interface);
        EXPECT_GT(ours.n_interface_nodes, 0);
      },
      grid.mesh);
}

TEST(StagesOnAnAssignedGrid, GiveWhatTheTypedCallsGive) {
  check_stages(generated_grid("venn", {16, 16}));
  check_stages(generated_grid("sphere", {8, 8, 8}));
}

// A grid given up to adapt (its points moved into the pipeline's frame in place) gives what
// the same grid lent gives, on grids whose frame is not the identity.
TEST(StagesOnAnAssignedGrid, AGridGivenUpAdaptsAsALentOne) {
  for (const auto& [name, dims] :
       {std::pair<std::string, std::vector<int>>{"venn", {16, 16}}, {"sphere", {8, 8, 8}}}) {
    AssignedGrid grid = generated_grid(name, dims);
    grid.material = assign::assign_materials(grid, {}).correction.labels;
    std::visit(
        [](auto& m) {  // in millimetres, far from the origin
          for (NodeId v : id_range<NodeId>(m.n_nodes()))
            m.set_point(v, 1e-3 * m.point(v) + Vec3(5, -3, 0));
          EXPECT_FALSE(unit_frame(m).is_identity());
        },
        grid.mesh);
    const AnyAdaptResult lent = adapt(grid);
    AssignedGrid copy = grid;
    const AnyAdaptResult given = adapt(std::move(copy));
    std::visit(
        [&](const auto& a) {
          using R = std::decay_t<decltype(a)>;
          ASSERT_TRUE(std::holds_alternative<R>(given));
          const R& b = std::get<R>(given);
          expect_same_mesh(a.mesh, b.mesh);
          EXPECT_EQ(a.material.raw(), b.material.raw());
          EXPECT_EQ(a.n_near_interface, b.n_near_interface);
          EXPECT_EQ(a.target.raw(), b.target.raw());
        },
        lent);
  }
}

TEST(StagesOnAnAssignedGrid, ThoseThatNeedAMaterialRefuseAGridWithoutOne) {
  const AssignedGrid grid = generated_grid("venn", {8, 8});
  ASSERT_FALSE(grid.assigned());
  EXPECT_THROW(reconstruct::reconstruct(grid, {}), InputError);
  EXPECT_THROW(adapt(grid), InputError);
}

}  // namespace
}  // namespace hexadapt
