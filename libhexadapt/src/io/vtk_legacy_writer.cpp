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

#include "hexadapt/io/atomic_file.h"
#include "hexadapt/io/vtk_legacy.h"
#include "vtk_cells.h"

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

// The title line: provenance as "key=value" pairs, one line of at most 255 characters, with
// as many whole pairs as fit (a pair cut in the middle read as another key or value).
std::string title_of(const MeshData& data) {
  std::string t = "hexadapt";
  const char* separator = ": ";
  for (const auto& [key, value] : data.metadata) {
    const std::string pair = separator + key + "=" + value;
    if (t.size() + pair.size() > 255) break;
    t += pair;
    separator = "; ";
  }
  for (char& c : t)
    if (c == '\n' || c == '\r') c = ' ';
  return t;
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
  write_section(b, data.cell_data, "CELL_DATA", static_cast<std::size_t>(data.n_cells()));
  write_section(b, data.point_data, "POINT_DATA", data.points.size());
  write_file_atomically(path, b.str());
}

}  // namespace hexadapt::io
