// Choosing the fraction arrays (io::FractionOptions::arrays): real solver output names them with
// spaces and commas ("Volume Fraction for Body, Nose").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/block.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

io::MeshData two_cells(const std::vector<std::string>& names) {
  io::MeshData d = io::from_mesh(make_quad_grid(2, 1));
  for (std::size_t k = 0; k < names.size(); ++k) {
    io::DataArray a;
    a.name = names[k];
    a.values = {k == 0 ? 1.0 : 0.0, k == 0 ? 0.0 : 1.0 / static_cast<double>(names.size() - 1)};
    d.set_cell_array(a);
  }
  return d;
}

TEST(FractionArrays, AnArrayIsNamedWholeWithItsCommasAndSpaces) {
  const io::MeshData d = two_cells({"Volume Fraction for Body, Nose", "Volume Fraction for Air"});
  io::FractionOptions o;
  o.arrays = {"Volume Fraction for Body, Nose", "Volume Fraction for Air"};
  const Fractions f = io::extract_fractions(d, o, nullptr, "in.vtu");
  EXPECT_EQ(f.names(), o.arrays);
  EXPECT_EQ(f(CellId(0), 0), 1.0);
  EXPECT_EQ(f(CellId(1), 1), 1.0);
}

TEST(FractionArrays, CommasSeparateNamesWhenNoArrayHoldsThemAll) {
  const io::MeshData d = two_cells({"vf_a", "vf_b", "vf_c"});
  io::FractionOptions o;
  o.arrays = {"vf_c,vf_a", "vf_b"};
  EXPECT_EQ(io::extract_fractions(d, o, nullptr, "in.vtu").names(),
            (std::vector<std::string>{"c", "a", "b"}));
}

TEST(FractionArrays, AMissingArrayIsNamedWithTheArraysThereAre) {
  const io::MeshData d = two_cells({"vf_a", "vf_b"});
  io::FractionOptions o;
  o.arrays = {"vf_a,vf_x"};
  try {
    io::extract_fractions(d, o, nullptr, "in.vtu");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("in.vtu"), std::string::npos) << what;
    EXPECT_NE(what.find("'vf_x'"), std::string::npos) << what;
    EXPECT_NE(what.find("'vf_a', 'vf_b'"), std::string::npos) << what;
  }
}

// --void naming a material that has an array: that material is the remainder, in its place,
// recomputed rather than read (it was refused as "also a fraction array").
TEST(FractionArrays, AVoidMaterialWithAnArrayIsRecomputedInItsPlace) {
  io::MeshData d = io::from_mesh(make_quad_grid(2, 1));
  d.set_cell_array({"vf_a", 1, io::ScalarType::float32, {0.5, 0.2}});
  d.set_cell_array({"vf_air", 1, io::ScalarType::float32, {0.7, 0.9}});  // noisy
  d.set_cell_array({"vf_b", 1, io::ScalarType::float32, {0.25, 0.3}});
  io::FractionOptions o;
  o.void_material = "air";
  const Fractions f = io::extract_fractions(d, o, nullptr, "in.vtu");
  EXPECT_EQ(f.names(), (std::vector<std::string>{"a", "air", "b"}));
  EXPECT_NEAR(f(CellId(0), 1), 0.25, 1e-15);
  EXPECT_NEAR(f(CellId(1), 1), 0.5, 1e-15);
  EXPECT_NEAR(f(CellId(1), 2), 0.3, 1e-15);
  o.void_material = "c";  // a new material, after the others
  EXPECT_EQ(io::extract_fractions(two_cells({"vf_a", "vf_b"}), o, nullptr, "in.vtu").names(),
            (std::vector<std::string>{"a", "b", "c"}));
}

// A sum above 1 cannot be helped by a void material: the message says what can (0.6 + 0.41
// is 1.0100000000000000089 in double, which a tolerance of 0.01 would still refuse).
TEST(FractionArrays, ASumAboveOneDoesNotAdviseAVoidMaterial) {
  io::MeshData d = io::from_mesh(make_quad_grid(1, 1));
  d.set_cell_array({"vf_a", 1, io::ScalarType::float64, {0.6}});
  d.set_cell_array({"vf_b", 1, io::ScalarType::float64, {0.41}});
  try {
    io::extract_fractions(d, io::FractionOptions{}, nullptr, "in.vtu");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find("void"), std::string::npos) << what;
    EXPECT_NE(what.find("{sum_tolerance} 0.011 would rescale this cell"), std::string::npos)
        << what;
  }
}

// On a rank, the tolerance that would accept every cell is known for the cells the rank
// holds only: the message says which (global ids 40-42 here), and names the failing cell by
// its global id.
TEST(FractionArrays, OnARankTheToleranceForEveryCellNamesTheCellsItCovers) {
  io::MeshData d = io::from_mesh(make_quad_grid(3, 1));
  d.set_cell_array({"vf_a", 1, io::ScalarType::float64, {0.6, 0.6, 0.6}});
  d.set_cell_array({"vf_b", 1, io::ScalarType::float64, {0.4, 0.42, 0.45}});
  dist::Block block = dist::Block::whole(3, d.n_points());
  block.cell_offset = 40;
  try {
    io::extract_fractions(d, io::FractionOptions{}, nullptr, "in.vtu", &block);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cell 41"), std::string::npos) << what;
    EXPECT_NE(what.find("{sum_tolerance} 0.051 every cell of cells 40-42 (this rank's part)"),
              std::string::npos)
        << what;
  }
}

// A partitioner's part of an unstructured mesh lists its cells' global ids: errors name the
// failing cell by its global id from the list.
TEST(FractionArrays, OnAListedPartErrorsNameTheCellsGlobalId) {
  io::MeshData d = io::from_mesh(make_quad_grid(3, 1));
  d.set_cell_array({"vf_a", 1, io::ScalarType::float64, {0.6, 0.6, 0.6}});
  d.set_cell_array({"vf_b", 1, io::ScalarType::float64, {0.4, 0.42, 0.45}});
  std::vector<std::int64_t> nodes(static_cast<std::size_t>(d.n_points()));
  for (std::size_t n = 0; n < nodes.size(); ++n) nodes[n] = static_cast<std::int64_t>(10 * n);
  const dist::Block block =
      dist::Block::listed({17, 90, 5}, 2, nodes, std::vector<char>(nodes.size(), 1));
  try {
    io::extract_fractions(d, io::FractionOptions{}, nullptr, "in.vtu", &block);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cell 90"), std::string::npos) << what;
    EXPECT_NE(what.find("every cell of the cells this rank holds"), std::string::npos) << what;
  }
  EXPECT_EQ(block.local_cell(5), CellId(2));
  EXPECT_EQ(block.local_cell(90), CellId(1));
  EXPECT_FALSE(block.local_cell(6).valid());
  EXPECT_EQ(block.local_node(30), NodeId(3));
  EXPECT_FALSE(block.local_node(31).valid());
}

}  // namespace
}  // namespace hexadapt
