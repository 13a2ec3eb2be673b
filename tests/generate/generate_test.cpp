#include "hexadapt/generate/generate.h"

#include <gtest/gtest.h>

#include "hexadapt/core/error.h"
#include "hexadapt/generate/extrusion.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::generate {
namespace {

GenerateOptions options(const std::string& name, std::vector<int> dims) {
  GenerateOptions o;
  o.case_name = name;
  o.dims = std::move(dims);
  o.samples = 3;
  return o;
}

TEST(Generate, EveryCaseRunsInEachOfItsDimensions) {
  for (const auto& c : cases()) {
    for (int dim : {2, 3}) {
      if (!c.defaults(dim).available) {
        EXPECT_THROW(generate(options(
                         c.name, dim == 2 ? std::vector<int>{4, 4} : std::vector<int>{4, 4, 4})),
                     OptionError);
        continue;
      }
      const auto r = generate(
          options(c.name, dim == 2 ? std::vector<int>{16, 12} : std::vector<int>{8, 7, 6}));
      EXPECT_EQ(r.data.dim, dim);
      EXPECT_EQ(r.data.n_cells(), dim == 2 ? 16 * 12 : 8 * 7 * 6);
      ASSERT_EQ(r.data.cell_data.size(), c.materials.size());
      EXPECT_EQ(r.data.cell_data[0].name, "vf_" + c.materials[0]);
      EXPECT_GT(r.mixed_cells, 0) << c.name;
      for (double v : r.volumes) EXPECT_GT(v, 0) << c.name;  // every material is present
    }
  }
}

TEST(Generate, SameOptionsSameArrays) {
  auto o = options("asteroid", {12, 12, 12});
  o.jitter = 0.2;
  o.seed = 5;
  const auto a = generate(o), b = generate(o);
  EXPECT_EQ(a.data.points, b.data.points);
  EXPECT_EQ(a.data.cells, b.data.cells);
  ASSERT_EQ(a.data.cell_data.size(), b.data.cell_data.size());
  for (std::size_t i = 0; i < a.data.cell_data.size(); ++i)
    EXPECT_EQ(a.data.cell_data[i].values, b.data.cell_data[i].values);
  EXPECT_EQ(a.data.metadata, b.data.metadata);
  o.seed = 6;
  EXPECT_NE(generate(o).data.cell_data[1].values, a.data.cell_data[1].values);
}

TEST(Generate, ExtrusionRepeatsTheFractionsInEveryLayer) {
  auto o = options("triple-point", {28, 12});
  const auto flat = generate(o);
  o.extrude = 3;
  o.jitter = 0.2;
  const auto thick = generate(o);
  EXPECT_EQ(thick.data.dim, 3);
  EXPECT_EQ(thick.data.n_cells(), 3 * 28 * 12);
  EXPECT_GE(thick.min_quality, 0.5);
  for (const auto& a : thick.data.cell_data) {
    const std::size_t n = 28 * 12;
    for (std::size_t l = 1; l < 3; ++l)
      for (std::size_t c = 0; c < n; ++c) ASSERT_EQ(a.values[l * n + c], a.values[c]) << a.name;
  }
  for (std::size_t m = 0; m < 3; ++m)  // layers of thickness 0.25 over [0,7]x[0,3]
    EXPECT_NEAR(thick.volumes[m], 0.75 * flat.volumes[m], 0.2) << m;
}

TEST(Generate, ExtrudedHexesAreWellFormed) {
  const io::MeshData q = io::from_mesh(make_quad_grid(3, 2));
  const HexMesh h = std::get<HexMesh>(io::to_mesh(extrude(q, 2, 0.5)));
  EXPECT_EQ(h.n_cells(), 12);
  EXPECT_EQ(h.n_nodes(), 12 * 3);
  for (CellId c : id_range<CellId>(h.n_cells())) {
    EXPECT_NEAR(h.cell_volume(c), 0.5, 1e-14);
    EXPECT_NEAR(h.cell_quality(c), 1.0, 1e-14);
  }
  EXPECT_FALSE(h.neighbour(CellId(0), 4).valid());
  EXPECT_EQ(h.neighbour(CellId(0), 5), CellId(6));
  EXPECT_THROW(extrude(q, 0, 1), OptionError);
  EXPECT_THROW(extrude(io::from_mesh(h), 1, 1), OptionError);
}

TEST(Generate, BoundsAndDimsAreChecked) {
  EXPECT_THROW(generate(options("no-such-case", {})), OptionError);
  EXPECT_THROW(generate(options("disk", {4})), OptionError);
  EXPECT_THROW(generate(options("disk", {0, 4})), OptionError);
  auto o = options("disk", {8, 8});
  o.bounds = Bounds{Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_THROW(generate(o), OptionError);
  o.bounds = Bounds{Vec3(0, 0, 0), Vec3(1, 1, 1)};  // 3D bounds for a 2D case
  EXPECT_THROW(generate(o), OptionError);
  o = options("sphere", {4, 4});
  EXPECT_THROW(generate(o), OptionError);
  o = options("sphere", {});
  o.extrude = 2;
  EXPECT_THROW(generate(o), OptionError);
}

TEST(Generate, RecordsTheCaseInTheMetadata) {
  const auto r = generate(options("stir", {16, 8}));
  bool found = false;
  for (const auto& [k, v] : r.data.metadata)
    if (k == "hexadapt_case") found = v == "stir";
  EXPECT_TRUE(found);
  EXPECT_EQ(r.time, 0.75);
  EXPECT_EQ(r.data.structured_cells, (std::array<int, 3>{16, 8, 0}));
}

}  // namespace
}  // namespace hexadapt::generate
