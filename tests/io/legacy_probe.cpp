// hexadapt_legacy_probe: a test helper for the Python cross-checks of the mesh file readers.
//   hexadapt_legacy_probe read FILE          prints FILE as JSON (points, cells, arrays)
//   hexadapt_legacy_probe rewrite IN OUT     reads IN and writes OUT (format by extension)
// Exit 0 on success, 2 with the error message on stderr when the library throws.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_file.h"

namespace {

using hexadapt::io::DataArray;
using hexadapt::io::ScalarType;
using nlohmann::json;

const char* type_name(ScalarType t) {
  switch (t) {
    case ScalarType::int8:
      return "int8";
    case ScalarType::uint8:
      return "uint8";
    case ScalarType::int16:
      return "int16";
    case ScalarType::uint16:
      return "uint16";
    case ScalarType::int32:
      return "int32";
    case ScalarType::uint32:
      return "uint32";
    case ScalarType::int64:
      return "int64";
    case ScalarType::uint64:
      return "uint64";
    case ScalarType::float32:
      return "float32";
    case ScalarType::float64:
      return "float64";
  }
  return "?";
}

json arrays_json(const std::vector<DataArray>& arrays) {
  json out = json::array();
  for (const DataArray& a : arrays)
    out.push_back({{"name", a.name},
                   {"components", a.n_components},
                   {"type", type_name(a.type)},
                   {"values", a.values}});
  return out;
}

json summary(const hexadapt::io::MeshData& d) {
  json points = json::array(), cells = json::array(), meta = json::object();
  for (const auto& p : d.points) points.push_back({p.x(), p.y(), p.z()});
  for (const auto& n : d.cells) cells.push_back(n.value());
  for (const auto& [k, v] : d.metadata) meta[k] = v;
  return {{"dim", d.dim},
          {"n_points", d.n_points()},
          {"n_cells", d.n_cells()},
          {"points", points},
          {"cells", cells},
          {"structured_cells", d.structured_cells},
          {"cell_data", arrays_json(d.cell_data)},
          {"point_data", arrays_json(d.point_data)},
          {"metadata", meta}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage = "usage: hexadapt_legacy_probe read FILE | rewrite IN OUT\n";
  if (argc < 3) return std::fputs(usage.c_str(), stderr), 1;
  const std::string verb = argv[1];
  try {
    if (verb == "read" && argc == 3) {
      std::cout << summary(hexadapt::io::read_mesh(argv[2])).dump() << "\n";
      return 0;
    }
    if (verb == "rewrite" && argc == 4) {
      auto data = hexadapt::io::read_mesh(argv[2]);
      data.metadata = {{"tool", "hexadapt_legacy_probe"}, {"input", argv[2]}};
      hexadapt::io::write_mesh(data, argv[3]);
      return 0;
    }
  } catch (const hexadapt::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::fputs(usage.c_str(), stderr);
  return 1;
}
