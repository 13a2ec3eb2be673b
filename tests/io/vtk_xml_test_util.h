// Helpers of the VTK XML tests: small meshes with arrays, files as strings.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

}  // namespace hexadapt::io::test
