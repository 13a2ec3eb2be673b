#include "hexadapt/io/text_case.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/fractions_reader.h"

namespace hexadapt::io {
namespace {

TEST(TextCase, Structured2DNumbersCellsJFastest) {
  // 2 x 3 cells; file cell 1 is (i=0, j=1), file cell 5 is (i=1, j=2).
  const MeshData d = read_text_case(
      "2\n2 3\n1\n2\n0 water\n2\n1 0.25\n5 1\n"
      "1 air\n1\n1 0.75\n",
      "t.txt");
  ASSERT_EQ(d.dim, 2);
  ASSERT_EQ(d.n_cells(), 6);
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{2, 3, 0}));
  const DataArray* w = d.find_cell_array("vf_water");
  const DataArray* a = d.find_cell_array("vf_air");
  ASSERT_TRUE(w && a);
  EXPECT_EQ(w->type, ScalarType::float64);
  EXPECT_EQ(w->values, (std::vector<double>{0, 0, 0.25, 0, 0, 1}));
  EXPECT_EQ(a->values, (std::vector<double>{0, 0, 0.75, 0, 0, 0}));
  // Unit cells from the origin: MeshData cell 5 = (1, 2) spans [1,2] x [2,3].
  EXPECT_EQ(d.points[d.cells[4 * 5 + 2].idx()], Vec3(2, 3, 0));
  EXPECT_EQ(d.cell_data.front().name, "vf_water");
}

TEST(TextCase, Structured3DNumbersCellsIFastest) {
  const MeshData d = read_text_case("3\n2 1 2\n1\n1\n7 steel\n1\n3 0.5\n", "t.txt");
  ASSERT_EQ(d.dim, 3);
  ASSERT_EQ(d.n_cells(), 4);
  EXPECT_EQ(d.find_cell_array("vf_steel")->values, (std::vector<double>{0, 0, 0, 0.5}));
  EXPECT_EQ(d.points[d.cells[8 * 3 + 7].idx()], Vec3(2, 1, 2));
}

TEST(TextCase, Unstructured2D) {
  const MeshData d = read_text_case(
      "2\n6\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n2\n4 0 1 4 3\n4 1 2 5 4\n"
      "1\n0 a\n2\n0 1\n1 0.5\n",
      "u.txt");
  ASSERT_EQ(d.dim, 2);
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(d.find_cell_array("vf_a")->values, (std::vector<double>{1, 0.5}));
}

// Several blocks (the reference implementation's 3x3x3 samples have two): each lists cells
// for materials known by name, a material of an earlier block continuing; a material first
// named in a later block comes after the earlier ones.
TEST(TextCase, BlocksListMoreCellsOfTheMaterialsOfTheSameName) {
  const MeshData d = read_text_case(
      "2\n2 2\n2\n"
      "2\n0 a\n2\n0 1\n1 0.5\n1 b\n1\n1 0.5\n"
      "2\n0 a\n1\n2 1\n1 c\n1\n3 1\n",
      "blocks.txt");
  ASSERT_EQ(d.cell_data.size(), 3u);
  EXPECT_EQ(d.cell_data[0].name, "vf_a");
  EXPECT_EQ(d.cell_data[1].name, "vf_b");
  EXPECT_EQ(d.cell_data[2].name, "vf_c");
  // File cells 0..3 are (i, j) = (0,0), (0,1), (1,0), (1,1); MeshData numbers i fastest.
  EXPECT_EQ(d.cell_data[0].values, (std::vector<double>{1, 1, 0.5, 0}));
  EXPECT_EQ(d.cell_data[1].values, (std::vector<double>{0, 0, 0.5, 0}));
  EXPECT_EQ(d.cell_data[2].values, (std::vector<double>{0, 0, 0, 1}));
}

struct Bad {
  const char* name;
  std::string content;
  std::string where, fragment;
};

TEST(TextCase, MalformedCasesNameTheLine) {
  const std::string head = "2\n2 2\n1\n1\n0 a\n";
  const std::vector<Bad> cases = {
      {"dimension", "4\n2 2\n", "line 1", "out of range [2, 3]"},
      {"second line", "3\n2 2\n", "line 1", "expected 3 cell counts"},
      {"no block", "2\n2 2\n0\n", "line 3", "out of range [1, 65536]"},
      {"second block missing", "2\n2 2\n2\n1\n0 a\n0\n", "line 6", "unexpected end of file"},
      {"listed twice over blocks", "2\n2 2\n2\n1\n0 a\n1\n3 0.5\n1\n0 a\n1\n3 0.5\n",
       "line 11", "cell 3 listed twice for material 'a'"},
      {"zero cells", "2\n0 2\n", "line 2", "out of range"},
      {"huge grid, no data", "2\n40000 40000\n1\n1\n0 a\n0\n", "line 2", "bytes follow"},
      {"listed too many", head + "5\n", "line 6", "out of range [0, 4]"},
      {"cell out of range", head + "1\n4 0.5\n", "line 7", "out of range [0, 3]"},
      {"negative cell", head + "1\n-1 0.5\n", "line 7", "out of range"},
      {"nan fraction", head + "1\n0 nan\n", "line 7", "not a number"},
      {"infinite fraction", head + "1\n0 inf\n", "line 7", "not a number"},
      {"bad number", head + "1\n0 0.5x\n", "line 7", "found '0.5x'"},
      {"truncated", head + "2\n0 0.5\n", "line 7", "unexpected end of file"},
      {"listed twice", head + "2\n0 0.5\n0 0.5\n", "line 8", "listed twice"},
      {"same material twice", "2\n2 2\n1\n2\n0 a\n0\n1 a\n0\n", "line 7", "listed twice"},
      {"trailing garbage", head + "0\nextra\n", "line 7", "unexpected 'extra'"},
      {"unstruct not quad", "2\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1\n3 0 1 2\n", "line 8",
       "expected 4"},
      {"unstruct node range", "2\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1\n4 0 1 2 4\n", "line 8",
       "out of range [0, 3]"},
      {"unstruct truncated nodes", "2\n4\n0 0 0\n1 0 0\n", "line 2", "node coordinates"},
  };
  for (const Bad& b : cases) {
    try {
      read_text_case(b.content, "bad.txt");
      ADD_FAILURE() << b.name << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "bad.txt");
      EXPECT_EQ(e.where(), b.where) << b.name << ": " << e.what();
      EXPECT_NE(e.message().find(b.fragment), std::string::npos) << b.name << ": " << e.what();
    }
  }
}

// The reader takes the values as written; the fraction options judge them, with the same
// tolerances as for every other format (it refused a sum of 1.000001 whatever
// --sum-tolerance said, and printed it as "1.000000, over 1").
TEST(TextCase, FractionsAreJudgedByTheFractionOptions) {
  const MeshData d = read_text_case("2\n2 1\n1\n2\n0 a\n2\n0 0.6\n1 1.00005\n1 b\n1\n0 0.40005\n", "t.txt");
  io::FractionOptions o;  // tolerances 1e-4: both cells pass, rescaled or clipped
  const Fractions f = io::extract_fractions(d, o, nullptr, "t.txt");
  EXPECT_NEAR(f(CellId(0), 0) + f(CellId(0), 1), 1.0, 1e-15);
  EXPECT_EQ(f(CellId(1), 0), 1.0);
  o.sum_tolerance = 1e-6;
  try {
    io::extract_fractions(d, o, nullptr, "t.txt");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "t.txt");
    EXPECT_EQ(e.where(), "cell 0");
    EXPECT_NE(e.message().find("1.00005"), std::string::npos) << e.what();
  }
  const MeshData over = read_text_case("2\n1 1\n1\n1\n0 a\n1\n0 1.5\n", "t.txt");
  EXPECT_THROW(io::extract_fractions(over, io::FractionOptions{}, nullptr, "t.txt"), InputError);
}

TEST(TextCase, EveryTestdataCaseReadsWithFractionsSummingToOne) {
  int n_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(HEXADAPT_TESTDATA)) {
    if (entry.path().extension() != ".txt") continue;
    ++n_files;
    const MeshData d = read_mesh(entry.path().string());
    SCOPED_TRACE(entry.path().filename().string());
    EXPECT_GT(d.n_cells(), 0);
    EXPECT_GE(d.cell_data.size(), 2u);
    std::vector<double> sum(static_cast<std::size_t>(d.n_cells()), 0.0);
    for (const DataArray& a : d.cell_data) {
      EXPECT_EQ(a.name.rfind("vf_", 0), 0u);
      for (std::size_t c = 0; c < sum.size(); ++c) sum[c] += a.values[c];
    }
    for (std::size_t c = 0; c < sum.size(); ++c) EXPECT_NEAR(sum[c], 1.0, 1e-9) << "cell " << c;
    // Every case is a valid mesh for the kernels.
    EXPECT_NO_THROW(to_mesh(d));
  }
  EXPECT_GE(n_files, 5);
}

TEST(TextCase, Figure2aCaseIsFiveBySeven) {
  const MeshData d = read_mesh(std::string(HEXADAPT_TESTDATA) + "/fig2a_5x7_three_materials.txt");
  EXPECT_EQ(d.structured_cells, (std::array<int, 3>{5, 7, 0}));
  EXPECT_EQ(d.cell_data.size(), 3u);
  // File cell 0 * 7 + 6 (i = 0, top-left) is all "top".
  EXPECT_EQ(d.find_cell_array("vf_top")->values[static_cast<std::size_t>(0 + 5 * 6)], 1.0);
}

}  // namespace
}  // namespace hexadapt::io
