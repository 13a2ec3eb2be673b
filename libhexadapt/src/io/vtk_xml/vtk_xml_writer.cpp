// Writing .vtu and .vts: the XML part is built with pugixml, the arrays follow as raw
// appended data (UInt64 headers, zlib blocks when asked).
#include <cstring>
#include <pugixml.hpp>
#include <sstream>

#include "../provenance.h"
#include "../vtk_xml_comment.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/atomic_file.h"
#include "hexadapt/io/material_names.h"
#include "hexadapt/io/vtk_xml.h"
#include "hexadapt/mesh/structured.h"
#include "vtk_xml_encode.h"
#include "vtk_xml_scalar.h"

namespace hexadapt::io {

namespace {

using detail::OutArray;

OutArray data_array(const DataArray& a) {
  const double* v = a.values.data();
  const ScalarType t = a.type;
  return {a.name, a.n_components, t, a.values.size(),
          [v, t](std::size_t first, std::size_t count, unsigned char* out) {
            detail::pack(v + first, count, t, out);
          }};
}

OutArray points_array(const MeshData& d) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "points are stored as packed xyz doubles");
  const double* xyz = d.points.empty() ? nullptr : d.points.front().data();
  return {"Points", 3, ScalarType::float64, 3 * d.points.size(),
          [xyz](std::size_t first, std::size_t count, unsigned char* out) {
            std::memcpy(out, xyz + first, count * sizeof(double));
          }};
}

template <class F>
OutArray int64_array(const char* name, std::size_t n, F value) {
  return {name, 1, ScalarType::int64, n,
          [value](std::size_t first, std::size_t count, unsigned char* out) {
            for (std::size_t k = 0; k < count; ++k) {
              const std::int64_t v = value(first + k);
              std::memcpy(out + 8 * k, &v, 8);
            }
          }};
}

// Connectivity in VTK's node order: hexes back from binary order, quads as they are.
std::vector<OutArray> cell_arrays(const MeshData& d) {
  const std::size_t npc = static_cast<std::size_t>(d.nodes_per_cell());
  const NodeId* cells = d.cells.data();
  const bool hex = d.dim == 3;
  std::vector<OutArray> out;
  out.push_back(int64_array("connectivity", d.cells.size(), [cells, hex](std::size_t i) {
    const std::size_t k =
        hex ? (i & ~std::size_t(7)) + std::size_t(ref_hex::vtk_of_binary[i & 7]) : i;
    return std::int64_t(cells[k].value());
  }));
  out.push_back(int64_array("offsets", static_cast<std::size_t>(d.n_cells()),
                            [npc](std::size_t c) { return std::int64_t((c + 1) * npc); }));
  const unsigned char type = hex ? 12 : 9;  // VTK_HEXAHEDRON, VTK_QUAD
  out.push_back(
      {"types", 1, ScalarType::uint8, static_cast<std::size_t>(d.n_cells()),
       [type](std::size_t, std::size_t count, unsigned char* o) { std::memset(o, type, count); }});
  return out;
}

// Builds the XML of a file and collects the arrays in the order of their offsets.
class XmlFile {
 public:
  XmlFile(const char* type, const WriteOptions& options, std::size_t largest_array) {
    encoding_.zlib = options.compress && largest_array > options.compress_above;
    encoding_.compress_above = options.compress_above;
    auto decl = doc_.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    root_ = doc_.append_child("VTKFile");
    root_.append_attribute("type") = type;
    root_.append_attribute("version") = "1.0";
    root_.append_attribute("byte_order") =
        detail::native_little_endian() ? "LittleEndian" : "BigEndian";
    root_.append_attribute("header_type") = "UInt64";
    if (encoding_.zlib) root_.append_attribute("compressor") = "vtkZLibDataCompressor";
    dataset_ = root_.append_child(type);
  }
  pugi::xml_node dataset() { return dataset_; }

  void add(pugi::xml_node parent, const OutArray& a) {
    pugi::xml_node e = parent.append_child("DataArray");
    e.append_attribute("type") = detail::vtk_name(a.type);
    e.append_attribute("Name") = a.name.c_str();
    e.append_attribute("NumberOfComponents") = a.n_components;
    e.append_attribute("format") = "appended";
    e.append_attribute("offset") = static_cast<unsigned long long>(offset_);
    if (encoding_.zlib) {
      arrays_.push_back({detail::encode_array(a, encoding_), {}});
      offset_ += arrays_.back().bytes.size();
    } else {
      // Plain data is converted while it is written: no copy of the whole array.
      arrays_.push_back({{}, a});
      offset_ += 8 + a.n_values * detail::scalar_size(a.type);
    }
  }

  // Metadata as one comment before <VTKFile>: meshio 5 rejects String field data (only the
  // material names are such an array, and they can be left out).
  void add_metadata(const MeshData& d) {
    if (d.metadata.empty()) return;
    doc_.insert_child_before(pugi::node_comment, root_)
        .set_value(detail::metadata_comment(d.metadata).c_str());
  }

  // String field-data arrays, the form ParaView shows (Information panel, spreadsheet view):
  // the material names, one per material index, and the exact command that made the file.
  void add_string_fields(const MeshData& d, const WriteOptions& options) {
    if (!options.string_fields) return;
    const std::vector<std::string> names = material_names(d);
    if (!names.empty()) add_string_field("material_names", names);
    if (const std::string* command = detail::last_command(d))
      add_string_field(detail::command_key, {*command});
  }

  void write(const std::string& path) {
    pugi::xml_node appended = root_.append_child("AppendedData");
    appended.append_attribute("encoding") = "raw";
    appended.append_child(pugi::node_pcdata).set_value("_");
    std::ostringstream xml;
    doc_.save(xml, "  ", pugi::format_indent, pugi::encoding_utf8);
    const std::string text = xml.str();
    const std::size_t mark = text.rfind("_</AppendedData>");
    if (mark == std::string::npos) throw InternalError("pugixml output lacks the appended marker");
    AtomicFile file(path);
    std::ofstream& out = file.stream();
    out.write(text.data(), static_cast<std::streamsize>(mark + 1));
    for (const Encoded& a : arrays_) {
      if (a.plain.fill)
        write_plain(out, a.plain);
      else
        out.write(reinterpret_cast<const char*>(a.bytes.data()),
                  static_cast<std::streamsize>(a.bytes.size()));
    }
    // A line break after the data, as VTK writes it (meshio's raw reader relies on it).
    out.write("\n  ", 3);
    out.write(text.data() + mark + 1, static_cast<std::streamsize>(text.size() - mark - 1));
    file.commit();
  }

 private:
  pugi::xml_document doc_;
  pugi::xml_node root_, dataset_;
  struct Encoded {
    std::vector<unsigned char> bytes;  ///< header and zlib blocks, or empty for plain data
    OutArray plain;                    ///< plain data to convert while writing
  };

  static void write_plain(std::ofstream& out, const OutArray& a) {
    const std::size_t size = detail::scalar_size(a.type);
    const std::uint64_t n_bytes = a.n_values * size;
    out.write(reinterpret_cast<const char*>(&n_bytes), 8);
    const std::size_t chunk = (std::size_t(1) << 20) / size;
    std::vector<unsigned char> buffer(chunk * size);
    for (std::size_t first = 0; first < a.n_values; first += chunk) {
      const std::size_t count = std::min(chunk, a.n_values - first);
      a.fill(first, count, buffer.data());
      out.write(reinterpret_cast<const char*>(buffer.data()),
                static_cast<std::streamsize>(count * size));
    }
  }

  // One String array: ascii character codes, each string ended by a 0.
  void add_string_field(const char* name, const std::vector<std::string>& strings) {
    if (!field_data_) field_data_ = dataset_.prepend_child("FieldData");
    std::string codes;
    for (const std::string& s : strings) {
      for (char c : s) codes += std::to_string(static_cast<unsigned char>(c)) + " ";
      codes += "0 ";
    }
    codes.pop_back();
    pugi::xml_node a = field_data_.append_child("DataArray");
    a.append_attribute("type") = "String";
    a.append_attribute("Name") = name;
    a.append_attribute("NumberOfTuples") = static_cast<unsigned long long>(strings.size());
    a.append_attribute("format") = "ascii";
    a.append_child(pugi::node_pcdata).set_value(codes.c_str());
  }

  pugi::xml_node field_data_;
  detail::Encoding encoding_;
  std::vector<Encoded> arrays_;
  std::size_t offset_ = 0;
};

std::size_t largest_array(const MeshData& d) {
  std::size_t n = std::max(d.points.size() * 24, d.cells.size() * 8);
  for (const auto* group : {&d.point_data, &d.cell_data})
    for (const DataArray& a : *group)
      n = std::max(n, a.values.size() * detail::scalar_size(a.type));
  return n;
}

void add_attributes(XmlFile& f, pugi::xml_node piece, const MeshData& d) {
  pugi::xml_node pd = piece.append_child("PointData");
  for (const DataArray& a : d.point_data) f.add(pd, data_array(a));
  pugi::xml_node cd = piece.append_child("CellData");
  for (const DataArray& a : d.cell_data) f.add(cd, data_array(a));
}

void check_writable(const MeshData& d, const std::string& path) {
  if (d.dim != 2 && d.dim != 3)
    throw OptionError(path + ": nothing to write: the data has no quad or hex cells");
  d.check_array_sizes(path);
}

// A block's Extent attribute: its first and last point index per axis in the whole grid.
std::string extent_text(const std::array<int, 3>& origin, const std::array<int, 3>& cells,
                        int dim) {
  std::string s;
  for (std::size_t a = 0; a < 3; ++a) {
    const int n = a < static_cast<std::size_t>(dim) ? cells[a] : 0;
    s += (a ? " " : "") + std::to_string(origin[a]) + " " + std::to_string(origin[a] + n);
  }
  return s;
}

// True when the cells are exactly the structured block of structured_cells.
bool is_structured(const MeshData& d) {
  const auto& n = d.structured_cells;
  if (n[0] < 1 || n[1] < 1 || (d.dim == 3) != (n[2] >= 1)) return false;
  const std::size_t np = std::size_t(n[0] + 1) * std::size_t(n[1] + 1) * std::size_t(n[2] + 1);
  if (d.points.size() != np) return false;
  std::vector<NodeId> expected;
  append_structured_cells(n[0], n[1], d.dim == 3 ? n[2] : 0, expected);
  return expected == d.cells;
}

}  // namespace

void write_vtu(const MeshData& data, const std::string& path, const WriteOptions& options) {
  check_writable(data, path);
  XmlFile f("UnstructuredGrid", options, largest_array(data));
  f.add_metadata(data);
  f.add_string_fields(data, options);
  pugi::xml_node piece = f.dataset().append_child("Piece");
  piece.append_attribute("NumberOfPoints") = static_cast<unsigned long long>(data.points.size());
  piece.append_attribute("NumberOfCells") = static_cast<long long>(data.n_cells());
  add_attributes(f, piece, data);
  f.add(piece.append_child("Points"), points_array(data));
  pugi::xml_node cells = piece.append_child("Cells");
  for (const OutArray& a : cell_arrays(data)) f.add(cells, a);
  f.write(path);
}

void write_vts(const MeshData& data, const std::string& path, const WriteOptions& options,
               const std::array<int, 3>& origin) {
  check_writable(data, path);
  if (!is_structured(data))
    throw OptionError(path +
                      ": a .vts needs a structured block of cells (structured_cells "
                      "set and matching the cells); write a .vtu instead");
  const std::string extent = extent_text(origin, data.structured_cells, data.dim);
  XmlFile f("StructuredGrid", options, largest_array(data));
  f.dataset().append_attribute("WholeExtent") = extent.c_str();
  f.add_metadata(data);
  f.add_string_fields(data, options);
  pugi::xml_node piece = f.dataset().append_child("Piece");
  piece.append_attribute("Extent") = extent.c_str();
  add_attributes(f, piece, data);
  f.add(piece.append_child("Points"), points_array(data));
  f.write(path);
}

std::string piece_path(const std::string& parallel, int piece) {
  const bool structured =
      parallel.size() > 5 && parallel.compare(parallel.size() - 5, 5, ".pvts") == 0;
  return parallel.substr(0, parallel.size() - 5) + "_" + std::to_string(piece) +
         (structured ? ".vts" : ".vtu");
}

namespace {

// The parallel file of `type` (PUnstructuredGrid, PStructuredGrid) with the arrays of
// `layout` declared, naming `pieces`: each piece's file and Extent. `whole` (the WholeExtent)
// and the Extents are empty for an unstructured grid.
void write_parallel(const MeshData& layout, const char* type, const std::string& whole,
                    const std::vector<std::pair<std::string, std::string>>& pieces,
                    const std::string& path) {
  check_writable(layout, path);
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  pugi::xml_node root = doc.append_child("VTKFile");
  root.append_attribute("type") = type;
  root.append_attribute("version") = "1.0";
  root.append_attribute("byte_order") =
      detail::native_little_endian() ? "LittleEndian" : "BigEndian";
  root.append_attribute("header_type") = "UInt64";
  if (!layout.metadata.empty())
    doc.insert_child_before(pugi::node_comment, root)
        .set_value(detail::metadata_comment(layout.metadata).c_str());
  pugi::xml_node grid = root.append_child(type);
  if (!whole.empty()) grid.append_attribute("WholeExtent") = whole.c_str();
  grid.append_attribute("GhostLevel") = 0;
  const auto declare = [](pugi::xml_node parent, const char* name, ScalarType t, int comps) {
    pugi::xml_node e = parent.append_child("PDataArray");
    e.append_attribute("type") = detail::vtk_name(t);
    e.append_attribute("Name") = name;
    e.append_attribute("NumberOfComponents") = comps;
  };
  pugi::xml_node pd = grid.append_child("PPointData");
  for (const DataArray& a : layout.point_data) declare(pd, a.name.c_str(), a.type, a.n_components);
  pugi::xml_node cd = grid.append_child("PCellData");
  for (const DataArray& a : layout.cell_data) declare(cd, a.name.c_str(), a.type, a.n_components);
  declare(grid.append_child("PPoints"), "Points", ScalarType::float64, 3);
  for (const auto& [source, extent] : pieces) {
    pugi::xml_node p = grid.append_child("Piece");
    if (!extent.empty()) p.append_attribute("Extent") = extent.c_str();
    p.append_attribute("Source") = source.c_str();
  }
  std::ostringstream xml;
  doc.save(xml, "  ", pugi::format_indent, pugi::encoding_utf8);
  const std::string text = xml.str();
  AtomicFile file(path);
  file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
  file.commit();
}

}  // namespace

void write_pvtu(const MeshData& layout, const std::vector<std::string>& pieces,
                const std::string& path) {
  std::vector<std::pair<std::string, std::string>> named;
  for (const std::string& p : pieces) named.emplace_back(p, "");
  write_parallel(layout, "PUnstructuredGrid", "", named, path);
}

void write_pvts(const MeshData& layout, const std::array<int, 3>& whole_cells,
                const std::vector<StructuredPiece>& pieces, const std::string& path) {
  std::vector<std::pair<std::string, std::string>> named;
  for (const StructuredPiece& p : pieces)
    named.emplace_back(p.file, extent_text(p.origin, p.cells, layout.dim));
  write_parallel(layout, "PStructuredGrid", extent_text({0, 0, 0}, whole_cells, layout.dim), named,
                 path);
}

}  // namespace hexadapt::io
