// io::extract_fractions judging a file's sums and traces: the stored precision and the tolerances
// used are reported, and a sum outside them is an error that says what would accept it.
#include <gtest/gtest.h>

#include <cfloat>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

using io::ScalarType;

// One cell per entry of `rows`, one array vf_<k> per column, all of type `type`.
io::MeshData cells(const std::vector<std::vector<double>>& rows, ScalarType type) {
  io::MeshData d = io::from_mesh(make_quad_grid(static_cast<int>(rows.size()), 1));
  for (std::size_t m = 0; m < rows.front().size(); ++m) {
    io::DataArray a{"vf_" + std::to_string(m), 1, type, {}};
    for (const auto& r : rows) a.values.push_back(r[m]);
    d.set_cell_array(a);
  }
  return d;
}

std::string message_of(const io::MeshData& d, const io::FractionOptions& o, std::string* where) {
  try {
    io::extract_fractions(d, o, nullptr, "in.vtu");
  } catch (const InputError& e) {
    if (where) *where = e.where();
    EXPECT_EQ(e.file(), "in.vtu");
    return e.message();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(FractionRepair, TheStoredPrecisionAndTheTolerancesDecidedAreReported) {
  const std::vector<std::vector<double>> rows = {{0.5, 0.25, 0.25}};
  io::FractionReport r;
  io::extract_fractions(cells(rows, ScalarType::float32), io::FractionOptions{}, &r);
  EXPECT_EQ(r.precision, StoredPrecision::float32);
  EXPECT_DOUBLE_EQ(r.tolerances.float32_rounding, 3 * static_cast<double>(FLT_EPSILON));
  EXPECT_EQ(r.tolerances.sum_tolerance, default_sum_tolerance);
  EXPECT_EQ(r.tolerances.zero_below, default_zero_below);
  EXPECT_FALSE(r.tolerances.sum_tolerance_given || r.tolerances.zero_below_given);
  io::extract_fractions(cells(rows, ScalarType::float64), io::FractionOptions{}, &r);
  EXPECT_EQ(r.precision, StoredPrecision::float64);
  EXPECT_EQ(r.tolerances.float32_rounding, 0);
  // One float32 array among float64 ones makes the data float32 ...
  io::MeshData mixed = cells(rows, ScalarType::float64);
  mixed.cell_data[1].type = ScalarType::float32;
  io::extract_fractions(mixed, io::FractionOptions{}, &r);
  EXPECT_EQ(r.precision, StoredPrecision::float32);
  // ... unless it is the void material's, recomputed rather than read.
  io::FractionOptions o;
  o.void_material = "1";
  o.sum_tolerance = 1e-3;
  io::extract_fractions(mixed, o, &r);
  EXPECT_EQ(r.precision, StoredPrecision::float64);
  EXPECT_EQ(r.tolerances.sum_tolerance, 1e-3);
  EXPECT_TRUE(r.tolerances.sum_tolerance_given);
}

// 12 materials: the float32 rounding of a cell is 12 FLT_EPSILON = 1.4e-6, and the trace
// threshold 8 times that (1.14e-5) for float32 data: 1.1e-5 of material 0 is then noise and
// set to 0, while it is kept in float64 data or when a threshold is given.
TEST(FractionRepair, TheTraceThresholdFollowsThePrecisionUnlessGiven) {
  std::vector<double> row(12, 0.0);
  row[0] = 1.1e-5;
  row[1] = 1 - 1.1e-5;
  io::FractionReport r;
  const Fractions f32 =
      io::extract_fractions(cells({row}, ScalarType::float32), io::FractionOptions{}, &r);
  EXPECT_EQ(f32(CellId(0), 0), 0.0);
  EXPECT_EQ(r.zeroed_values, 1);
  EXPECT_DOUBLE_EQ(r.tolerances.zero_below, 8 * 12 * static_cast<double>(FLT_EPSILON));
  const Fractions f64 =
      io::extract_fractions(cells({row}, ScalarType::float64), io::FractionOptions{}, &r);
  EXPECT_NEAR(f64(CellId(0), 0), 1.1e-5, 1e-18);
  EXPECT_EQ(r.zeroed_values, 0);
  io::FractionOptions given;
  given.zero_below = 1e-5;
  const Fractions g = io::extract_fractions(cells({row}, ScalarType::float32), given, &r);
  EXPECT_NEAR(g(CellId(0), 0), 1.1e-5, 1e-18);
  EXPECT_TRUE(r.tolerances.zero_below_given);
}

// Sums of 1.00213 and 1.00473 in float32 data: not rounding (that is at most 2.4e-7 here),
// so the default rejects them; the message names the cell and its sum, says the tolerance
// was the float32 default, and gives the --sum-tolerance for this cell and for every cell.
// A void material cannot help a sum above 1: it is not advised, and naming one changes
// nothing.
TEST(FractionRepair, ASumAboveOneNamesTheToleranceThatWouldAcceptIt) {
  const io::MeshData d = cells({{0.5, 0.5}, {0.6, 0.40213}, {0.5, 0.50473}}, ScalarType::float32);
  for (const char* void_material : {"", "air"}) {
    io::FractionOptions o;
    o.void_material = void_material;
    std::string where;
    const std::string m = message_of(d, o, &where);
    EXPECT_EQ(where, "cell 1");
    EXPECT_NE(m.find("sum to 1.00213 (0.00213 above 1; sum tolerance 0.0001, the default for "
                     "float32 data)"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("{sum_tolerance} 0.0022 would rescale this cell, {sum_tolerance} 0.0048 "
                     "every cell"),
              std::string::npos)
        << m;
    EXPECT_EQ(m.find("void"), std::string::npos) << m;
  }
  io::FractionOptions o;
  o.sum_tolerance = 0.0022;
  std::string where;
  const std::string m = message_of(d, o, &where);
  EXPECT_EQ(where, "cell 2");
  EXPECT_NE(m.find("sum tolerance 0.0022, given"), std::string::npos) << m;
  EXPECT_NE(m.find("{sum_tolerance} 0.0048 would rescale this cell"), std::string::npos) << m;
  EXPECT_EQ(m.find("every cell"), std::string::npos) << m;  // this cell is the worst
  o.sum_tolerance = 0.0048;
  io::FractionReport r;
  const Fractions f = io::extract_fractions(d, o, &r);
  EXPECT_NEAR(f(CellId(2), 0) + f(CellId(2), 1), 1.0, 1e-15);
  EXPECT_EQ(r.rescaled_cells, 2);
  EXPECT_NEAR(r.max_sum_error, 0.00473, 1e-12);
}

// A sum below 1 can also take a void material: both ways are offered.
TEST(FractionRepair, ASumBelowOneOffersAVoidMaterialOrATolerance) {
  const io::MeshData d = cells({{0.5, 0.4687}, {0.5, 0.5}}, ScalarType::float64);
  std::string where;
  const std::string m = message_of(d, io::FractionOptions{}, &where);
  EXPECT_EQ(where, "cell 0");
  EXPECT_NE(m.find("sum to 0.9687 (0.0313 below 1; sum tolerance 0.0001, the default for "
                   "float64 data): name a void material ({void_material} NAME) to receive the "
                   "remainder, or {sum_tolerance} 0.032 would rescale this cell"),
            std::string::npos)
      << m;
}

}  // namespace
}  // namespace hexadapt
