// The real inputs of ../shared/data (DESIGN sec. 7.2), when this checkout has them beside it.
// A fresh clone does not: then these tests are skipped.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io {
namespace {

namespace fs = std::filesystem;

fs::path shared_data() {
  return fs::path(HEXADAPT_TESTDATA) / ".." / ".." / "shared" / "data";
}

// Every cell's fractions sum to ~1 (raw solver values: within 1e-4).
void expect_fractions(const MeshData& d, const std::vector<std::string>& materials) {
  std::vector<double> sum(static_cast<std::size_t>(d.n_cells()), 0.0);
  for (const std::string& m : materials) {
    const DataArray* a = d.find_cell_array("vf_" + m);
    ASSERT_NE(a, nullptr) << m;
    ASSERT_EQ(a->n_components, 1);
    for (std::size_t c = 0; c < sum.size(); ++c) sum[c] += a->values[c];
  }
  double worst = 0;
  for (double s : sum) worst = std::max(worst, std::abs(s - 1));
  EXPECT_LT(worst, 1e-4);
}

TEST(RealData, TriplePoint420x180Binary) {
  const fs::path dir = shared_data() / "triplepoint";
  if (!fs::exists(dir)) GTEST_SKIP() << "no " << dir;
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".vtk") continue;
    SCOPED_TRACE(e.path().string());
    const MeshData d = read_mesh(e.path().string());
    EXPECT_EQ(d.dim, 2);
    EXPECT_EQ(d.n_cells(), 420 * 180);
    EXPECT_EQ(d.structured_cells, (std::array<int, 3>{420, 180, 0}));
    EXPECT_EQ(d.cell_data.size(), 3u);
    EXPECT_EQ(d.find_cell_array("vf_region1")->type, ScalarType::float32);
    EXPECT_NEAR(d.points.back().x(), 7.0, 1e-9);
    EXPECT_NEAR(d.points.back().y(), 3.0, 1e-9);
    expect_fractions(d, {"region1", "region2", "region3"});
    ++n;
  }
  EXPECT_GT(n, 0);
}

TEST(RealData, OpenFoamDamBreakAscii) {
  const fs::path root = shared_data() / "openfoam";
  if (!fs::exists(root)) GTEST_SKIP() << "no " << root;
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"damBreak", {"water", "air", "obstacle"}},
      {"damBreak4phase", {"water", "oil", "mercury", "air", "obstacle"}}};
  for (const auto& [name, materials] : cases) {
    for (const auto& e : fs::directory_iterator(root / name)) {
      SCOPED_TRACE(e.path().string());
      const MeshData d = read_mesh(e.path().string());
      EXPECT_EQ(d.n_cells(), 46 * 50);
      EXPECT_EQ(d.structured_cells, (std::array<int, 3>{46, 50, 0}));
      EXPECT_EQ(d.cell_data.size(), materials.size());
      expect_fractions(d, materials);
    }
  }
}

}  // namespace
}  // namespace hexadapt::io
