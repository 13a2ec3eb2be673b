// Helpers of the io tests: small meshes with arrays, files as strings, mesh comparisons.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::io::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Named after the running test too: ctest runs the tests of one file in parallel processes,
// which must not write, read and remove the same file.
inline std::string temp_path(const std::string& name) {
  const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = t ? std::string(t->test_suite_name()) + "." + t->name() + "_" : "";
  return (std::filesystem::temp_directory_path() / ("hexadapt_xml_" + test + name)).string();
}

// A perturbed n x n x n hex grid (or n x n quads) with one array of every type.
inline MeshData sample_mesh(int n, bool hexes) {
  MeshData d = hexes ? from_mesh(make_hex_grid(n, n, n)) : from_mesh(make_quad_grid(n, n));
  d.structured_cells = {n, n, hexes ? n : 0};
  for (std::size_t k = 0; k < d.points.size(); ++k)
    d.points[k] += Vec3(1e-3 * static_cast<double>(k % 7), 2e-3 * static_cast<double>(k % 5),
                        hexes ? 1e-3 * static_cast<double>(k % 3) : 0.0);
  const auto types = {ScalarType::int8,   ScalarType::uint8,  ScalarType::int16,
                      ScalarType::uint16, ScalarType::int32,  ScalarType::uint32,
                      ScalarType::int64,  ScalarType::uint64, ScalarType::float32,
                      ScalarType::float64};
  int k = 0;
  for (ScalarType t : types) {
    DataArray a;
    a.name = "cell_" + std::to_string(k++);
    a.type = t;
    for (index_t c = 0; c < d.n_cells(); ++c)
      a.values.push_back(t == ScalarType::float64 ? 0.1 * c - 3.0
                         : t == ScalarType::float32
                             ? static_cast<double>(0.5f * static_cast<float>(c))
                             : static_cast<double>(c % 100));
    d.set_cell_array(a);
  }
  DataArray v;
  v.name = "velocity";
  v.n_components = 3;
  for (std::size_t p = 0; p < d.points.size(); ++p)
    v.values.insert(v.values.end(),
                    {d.points[p].x(), -d.points[p].y(), 1.0 / (1.0 + static_cast<double>(p))});
  d.set_point_array(v);
  d.metadata = {{"tool", "hexadapt-test"}, {"options", "--x <a & b> \"q\""}};
  return d;
}

// The head of an ASCII legacy .vtk file, before its DATASET line.
inline const std::string kLegacyHead = "# vtk DataFile Version 3.0\ntest case\nASCII\n";

// The cells' node ids as plain ints (readable in a failing EXPECT_EQ).
inline std::vector<int> cell_ids(const MeshData& d) {
  std::vector<int> out;
  for (NodeId n : d.cells) out.push_back(n.value());
  return out;
}

// The first byte of a VTK XML file's appended data (after the '_' marker).
inline std::size_t appended_start(const std::string& s) {
  return s.find('_', s.find("<AppendedData")) + 1;
}

// Two meshes carry the same geometry, cells, arrays (names, types, components, values) and
// metadata.
inline void expect_same(const MeshData& a, const MeshData& b) {
  ASSERT_EQ(a.dim, b.dim);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k) EXPECT_EQ(a.points[k], b.points[k]) << k;
  EXPECT_EQ(a.cells, b.cells);
  ASSERT_EQ(a.cell_data.size(), b.cell_data.size());
  for (std::size_t k = 0; k < a.cell_data.size(); ++k) {
    EXPECT_EQ(a.cell_data[k].name, b.cell_data[k].name);
    EXPECT_EQ(a.cell_data[k].type, b.cell_data[k].type) << a.cell_data[k].name;
    EXPECT_EQ(a.cell_data[k].values, b.cell_data[k].values) << a.cell_data[k].name;
  }
  ASSERT_EQ(a.point_data.size(), b.point_data.size());
  for (std::size_t k = 0; k < a.point_data.size(); ++k) {
    EXPECT_EQ(a.point_data[k].name, b.point_data[k].name);
    EXPECT_EQ(a.point_data[k].n_components, b.point_data[k].n_components);
    EXPECT_EQ(a.point_data[k].values, b.point_data[k].values);
  }
  EXPECT_EQ(a.metadata, b.metadata);
}

}  // namespace hexadapt::io::test
