#include "hexadapt/adapt/adapt_io.h"

#include <gtest/gtest.h>

#include "adapt/adapt_cases.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/assigned_grid_file.h"

namespace hexadapt {
namespace {

TEST(AdaptIo, MaterialArrayIsCheckedCellByCell) {
  io::MeshData data = io::from_mesh(make_quad_grid(3, 1));
  EXPECT_THROW(io::read_material_array(data, 2, "a.vtu"), InputError);  // missing
  data.set_cell_array({"material", 1, io::ScalarType::int32, {0, 1, 1}});
  const auto m = io::read_material_array(data, 2, "a.vtu");
  EXPECT_EQ(m[CellId(1)], 1);
  data.set_cell_array({"material", 1, io::ScalarType::float64, {0, 1.5, 1}});
  try {
    io::read_material_array(data, 2, "a.vtu");
    FAIL() << "a fractional material was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "a.vtu");
    EXPECT_EQ(e.where(), "cell 1");
  }
  data.set_cell_array({"material", 1, io::ScalarType::int32, {0, 2, 1}});
  EXPECT_THROW(io::read_material_array(data, 2, "a.vtu"), InputError);
}

TEST(AdaptIo, OutputCarriesMaterialTargetAndDistance) {
  const QuadMesh grid = make_quad_grid(8, 8);
  const Fractions f = test::sample_fractions(
      grid, [](const Vec3& p) { return (p - Vec3(4.2, 3.9, 0)).norm() < 2.6; }, 2, 8);
  const auto r = adapt(grid, f, majority_materials(f));
  const io::MeshData d = adapt_mesh_data(r, {"outside", "disk"});
  EXPECT_EQ(d.dim, 2);
  EXPECT_EQ(d.n_cells(), r.mesh.n_cells());
  const io::DataArray* m = d.find_cell_array("material");
  const io::DataArray* t = d.find_point_array("target");
  const io::DataArray* dist = d.find_point_array("distance");
  ASSERT_TRUE(m && t && dist);
  EXPECT_EQ(t->n_components, 3);
  EXPECT_EQ(t->n_tuples(), static_cast<std::size_t>(r.mesh.n_nodes()));
  for (CellId c : id_range<CellId>(r.mesh.n_cells())) EXPECT_EQ(m->values[c.idx()], r.material[c]);
  for (NodeId v : id_range<NodeId>(r.mesh.n_nodes())) {
    const Vec3 tv(t->values[3 * v.idx()], t->values[3 * v.idx() + 1], t->values[3 * v.idx() + 2]);
    EXPECT_NEAR(dist->values[v.idx()], (tv - r.mesh.point(v)).norm(), 1e-12);
  }
}

}  // namespace
}  // namespace hexadapt
