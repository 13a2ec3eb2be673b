// Legacy VTK writer: binary UNSTRUCTURED_GRID in the classic CELLS / CELL_TYPES layout
// (file version 4.2), which VTK 9, ParaView and meshio all read. One-component arrays are
// written as SCALARS, the others in one FIELD block per section; every array keeps its type.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "../provenance.h"
#include "../vtk_cells.h"
#include "../vtk_xml_comment.h"
#include "hexadapt/io/atomic_file.h"
#include "hexadapt/io/vtk_legacy.h"

namespace hexadapt::io {

namespace {

// Integer arrays hold integers in range when they come from a file; anything else (NaN, a
// value set by hand beyond the type) is clamped rather than converted with undefined results.
template <class T, class V>
T convert(V v) {
  if constexpr (std::is_integral_v<T> && std::is_floating_point_v<V>) {
    if (!(v == v)) return T(0);
    if (v <= static_cast<V>(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
    if (v >= static_cast<V>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
  }
  return static_cast<T>(v);
}

// Values are converted and byte-swapped in blocks: one resize per block, no per-value append.
class BigEndianBuffer {
 public:
  /// Appends n values produced by value(k), stored as T in big-endian order.
  template <class T, class F>
  void put_block(std::size_t n, F value) {
    const std::size_t at = out_.size();
    out_.resize(at + n * sizeof(T));
    char* p = out_.data() + at;
    for (std::size_t k = 0; k < n; ++k, p += sizeof(T)) {
      const T v = convert<T>(value(k));
      std::array<char, sizeof(T)> b;
      std::memcpy(b.data(), &v, sizeof(T));
      std::reverse_copy(b.begin(), b.end(), p);
    }
  }
  void text(const std::string& s) { out_ += s; }
  std::string& str() { return out_; }

 private:
  std::string out_;
};

const char* legacy_name(ScalarType t) {
  switch (t) {
    case ScalarType::int8:
      return "char";
    case ScalarType::uint8:
      return "unsigned_char";
    case ScalarType::int16:
      return "short";
    case ScalarType::uint16:
      return "unsigned_short";
    case ScalarType::int32:
      return "int";
    case ScalarType::uint32:
      return "unsigned_int";
    // meshio's 4.2 reader knows no vtktypeint64; VTK reads long as 8 bytes on LP64 systems.
    case ScalarType::int64:
      return "long";
    case ScalarType::uint64:
      return "unsigned_long";
    case ScalarType::float32:
      return "float";
    case ScalarType::float64:
      return "double";
  }
  return "double";
}

void put_values(BigEndianBuffer& b, const DataArray& a) {
  const std::size_t n = a.values.size();
  const auto v = [&](std::size_t k) { return a.values[k]; };
  switch (a.type) {
    case ScalarType::int8:
      b.put_block<std::int8_t>(n, v);
      break;
    case ScalarType::uint8:
      b.put_block<std::uint8_t>(n, v);
      break;
    case ScalarType::int16:
      b.put_block<std::int16_t>(n, v);
      break;
    case ScalarType::uint16:
      b.put_block<std::uint16_t>(n, v);
      break;
    case ScalarType::int32:
      b.put_block<std::int32_t>(n, v);
      break;
    case ScalarType::uint32:
      b.put_block<std::uint32_t>(n, v);
      break;
    case ScalarType::int64:
      b.put_block<std::int64_t>(n, v);
      break;
    case ScalarType::uint64:
      b.put_block<std::uint64_t>(n, v);
      break;
    case ScalarType::float32:
      b.put_block<float>(n, v);
      break;
    case ScalarType::float64:
      b.put_block<double>(n, v);
      break;
  }
  b.text("\n");
}

// Names cannot hold whitespace in the legacy format: VTK's own %XX escape.
std::string encode_name(const std::string& name) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= ' ' || u >= 127 || c == '%') {
      out += '%';
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += c;
    }
  }
  return out.empty() ? std::string("unnamed") : out;
}

// The metadata as "key=value" pairs, this file's own provenance first: the entries from the
// last `hexadapt_tool` on (the tool that wrote the file, its version and command, what it
// added), then those of the files it read. A line break would end the title: a space.
std::vector<std::string> title_pairs(const MeshData& data) {
  const auto& md = data.metadata;
  std::size_t own = 0;
  for (std::size_t i = 0; i < md.size(); ++i)
    if (md[i].first == "hexadapt_tool") own = i;
  std::vector<std::string> pairs;
  for (std::size_t k = 0; k < md.size(); ++k) {
    const auto& [key, value] = md[(own + k) % md.size()];
    std::string pair = key + "=" + value;
    std::replace(pair.begin(), pair.end(), '\n', ' ');
    std::replace(pair.begin(), pair.end(), '\r', ' ');
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

// "hexadapt: pair; pair; ..." with the pairs that fit in `limit` characters, whole.
std::string whole_pairs(const std::vector<std::string>& pairs, std::size_t limit,
                        std::size_t& left_out) {
  std::string t = "hexadapt";
  const std::size_t empty = t.size();
  left_out = 0;
  for (const std::string& pair : pairs) {
    const char* separator = t.size() == empty ? ": " : "; ";
    if (t.size() + 2 + pair.size() > limit) {
      ++left_out;
      continue;
    }
    t += separator + pair;
  }
  return t;
}

// The title line: as many whole pairs as its 255 characters hold (VTK reads no more); a pair
// is never cut (its end would read as another value). When some are left out the line ends
// with "; ... N more"; the command is kept whole in the data-set field data anyway.
std::string title_of(const MeshData& data) {
  constexpr std::size_t limit = 255, mark_room = 16;
  const std::vector<std::string> pairs = title_pairs(data);
  std::size_t left_out = 0;
  std::string t = whole_pairs(pairs, limit, left_out);
  if (left_out == 0) return t;
  t = whole_pairs(pairs, limit - mark_room, left_out);
  return t + "; ... " + std::to_string(left_out) + " more";
}

// The exact command that made the file and every metadata entry (the title holds only what
// fits in 255 characters), as char arrays of the data set's field data: VTK and ParaView
// read them as vtkCharArrays, meshio as int8 field data (it refuses String arrays; after the
// cells, as there, meshio files them under field_data), our reader back as the metadata.
void write_metadata_fields(BigEndianBuffer& b, const MeshData& data) {
  std::vector<std::pair<const char*, std::string>> fields;
  if (const std::string* command = detail::last_command(data); command && !command->empty())
    fields.emplace_back(detail::command_key, *command);
  if (!data.metadata.empty())
    fields.emplace_back(detail::metadata_key, detail::metadata_comment(data.metadata));
  if (fields.empty()) return;
  b.text("FIELD FieldData " + std::to_string(fields.size()) + "\n");
  for (const auto& [key, text] : fields)
    b.text(std::string(key) + " 1 " + std::to_string(text.size()) + " char\n" + text + "\n");
}

void write_section(BigEndianBuffer& b, const std::vector<DataArray>& arrays, const char* keyword,
                   std::size_t n) {
  if (arrays.empty()) return;
  b.text(std::string(keyword) + " " + std::to_string(n) + "\n");
  std::size_t n_field = 0;
  for (const DataArray& a : arrays) {
    if (a.n_components != 1) {
      ++n_field;
      continue;
    }
    b.text("SCALARS " + encode_name(a.name) + " " + legacy_name(a.type) +
           " 1\nLOOKUP_TABLE default\n");
    put_values(b, a);
  }
  if (n_field == 0) return;
  b.text("FIELD FieldData " + std::to_string(n_field) + "\n");
  for (const DataArray& a : arrays)
    if (a.n_components != 1) {
      b.text(encode_name(a.name) + " " + std::to_string(a.n_components) + " " +
             std::to_string(a.n_tuples()) + " " + legacy_name(a.type) + "\n");
      put_values(b, a);
    }
}

void write_cells(BigEndianBuffer& b, const MeshData& data) {
  const auto n = static_cast<std::size_t>(data.n_cells());
  const auto k = static_cast<std::size_t>(data.nodes_per_cell());
  b.text("CELLS " + std::to_string(n) + " " + std::to_string(n * (k + 1)) + "\n");
  // Per cell: its node count, then its nodes (hexes from binary lattice order to VTK's).
  b.put_block<std::int32_t>(n * (k + 1), [&](std::size_t e) {
    const std::size_t c = e / (k + 1), i = e % (k + 1);
    if (i == 0) return static_cast<index_t>(k);
    const std::size_t from =
        data.dim == 3 ? static_cast<std::size_t>(ref_hex::vtk_of_binary[i - 1]) : i - 1;
    return data.cells[c * k + from].value();
  });
  b.text("\nCELL_TYPES " + std::to_string(n) + "\n");
  const std::int32_t type = data.dim == 3 ? detail::vtk_hexahedron : detail::vtk_quad;
  b.put_block<std::int32_t>(n, [&](std::size_t) { return type; });
  b.text("\n");
}

}  // namespace

void write_vtk_legacy(const MeshData& data, const std::string& path) {
  BigEndianBuffer b;
  b.text("# vtk DataFile Version 4.2\n" + title_of(data) + "\nBINARY\nDATASET UNSTRUCTURED_GRID\n");
  b.text("POINTS " + std::to_string(data.points.size()) + " double\n");
  b.put_block<double>(3 * data.points.size(),
                      [&](std::size_t e) { return data.points[e / 3][static_cast<int>(e % 3)]; });
  b.text("\n");
  write_cells(b, data);
  write_metadata_fields(b, data);
  write_section(b, data.cell_data, "CELL_DATA", static_cast<std::size_t>(data.n_cells()));
  write_section(b, data.point_data, "POINT_DATA", data.points.size());
  write_file_atomically(path, b.str());
}

}  // namespace hexadapt::io
