// Test driver for the Python checks of the VTK XML reader and writers: reads a file with
// read_vtk_xml, prints everything it read as JSON on stdout and optionally writes it back
// with write_vtu / write_vts.
//
//   hexadapt_io_roundtrip IN [--vtu OUT] [--vts OUT] [--raw] [--meta KEY=VALUE]...
#include <cstring>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"

namespace {

const char* type_name(hexadapt::io::ScalarType t) {
  static const char* names[] = {"Int8",   "UInt8", "Int16",  "UInt16",  "Int32",
                                "UInt32", "Int64", "UInt64", "Float32", "Float64"};
  return names[static_cast<int>(t)];
}

nlohmann::json arrays(const std::vector<hexadapt::io::DataArray>& list) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& a : list)
    out.push_back({{"name", a.name},
                   {"type", type_name(a.type)},
                   {"n_components", a.n_components},
                   {"values", a.values}});
  return out;
}

nlohmann::json summary(const hexadapt::io::MeshData& d) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : d.points) points.push_back({p.x(), p.y(), p.z()});
  std::vector<int> cells;
  for (auto n : d.cells) cells.push_back(n.value());
  nlohmann::json meta = nlohmann::json::object();
  for (const auto& [k, v] : d.metadata) meta[k] = v;
  return {{"dim", d.dim},
          {"points", points},
          {"cells", cells},
          {"structured_cells", d.structured_cells},
          {"point_data", arrays(d.point_data)},
          {"cell_data", arrays(d.cell_data)},
          {"metadata", meta}};
}

int run(int argc, char** argv) {
  if (argc < 2) {
    std::cerr
        << "usage: hexadapt_io_roundtrip IN [--vtu OUT] [--vts OUT] [--raw] [--meta K=V]...\n";
    return 1;
  }
  std::ifstream in(argv[1], std::ios::binary);
  if (!in) throw hexadapt::IoError(std::string(argv[1]) + ": cannot open");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string content = buffer.str();
  hexadapt::io::MeshData data = hexadapt::io::read_vtk_xml(content, argv[1]);
  hexadapt::io::WriteOptions options;
  options.compress_above = 500;  // the small test meshes get both stored and compressed arrays
  for (int k = 2; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--raw") options.compress = false;
    if (arg == "--meta" && k + 1 < argc) {
      const std::string kv = argv[++k];
      const auto eq = kv.find('=');
      data.metadata.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    }
  }
  for (int k = 2; k + 1 < argc; ++k) {
    if (std::strcmp(argv[k], "--vtu") == 0) hexadapt::io::write_vtu(data, argv[k + 1], options);
    if (std::strcmp(argv[k], "--vts") == 0) hexadapt::io::write_vts(data, argv[k + 1], options);
  }
  std::cout << summary(data).dump() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const hexadapt::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
