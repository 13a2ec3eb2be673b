#include "legacy_attributes.h"

#include <algorithm>
#include <optional>
#include <string>

#include "../provenance.h"
#include "../vtk_xml_comment.h"
#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

namespace {

struct Section {
  bool cells = true;
  std::size_t n_tuples = 0;
};

// Two arrays of one section with the same name are refused, as the XML reader does: keeping
// either would silently drop the other.
void add_array(LegacyScanner& s, MeshData& data, const Section& sec, DataArray a) {
  if ((sec.cells ? data.find_cell_array(a.name) : data.find_point_array(a.name)) != nullptr)
    s.fail(std::string("two ") + (sec.cells ? "CELL_DATA" : "POINT_DATA") + " arrays named " +
           quote_token(a.name));
  if (sec.cells)
    data.set_cell_array(std::move(a));
  else
    data.set_point_array(std::move(a));
}

DataArray read_array(LegacyScanner& s, const Section& sec, std::string name, int n_comp) {
  const LegacyType& t = s.data_type();
  DataArray a;
  a.name = std::move(name);
  a.n_components = n_comp;
  a.type = t.type;
  a.values = s.reals(t, sec.n_tuples * static_cast<std::size_t>(n_comp), "array values");
  return a;
}

void read_scalars(LegacyScanner& s, MeshData& data, const Section& sec) {
  std::string name = decode_name(s.expect_token("an array name"));
  const LegacyType& t = s.data_type();
  int n_comp = 1;
  // The component count is optional; LOOKUP_TABLE is required by VTK but tolerated absent.
  std::string_view next = s.peek_token();
  if (!next.empty() && next.front() >= '0' && next.front() <= '9')
    n_comp = static_cast<int>(s.integer("a number of components", 1, 4));
  if (keyword_is(s.peek_token(), "LOOKUP_TABLE")) {
    s.token();
    s.expect_token("a lookup table name");
  }
  DataArray a;
  a.name = std::move(name);
  a.n_components = n_comp;
  a.type = t.type;
  a.values = s.reals(t, sec.n_tuples * static_cast<std::size_t>(n_comp), "array values");
  add_array(s, data, sec, std::move(a));
}

// COLOR_SCALARS are floats in [0,1] in ASCII files and unsigned chars in binary ones.
void read_color_scalars(LegacyScanner& s, MeshData& data, const Section& sec) {
  std::string name = decode_name(s.expect_token("an array name"));
  const int n_comp = static_cast<int>(s.integer("a number of color components", 1, 4));
  DataArray a;
  a.name = std::move(name);
  a.n_components = n_comp;
  a.type = ScalarType::float32;
  static constexpr LegacyType kByte{"unsigned_char", ScalarType::uint8, 1, false};
  static constexpr LegacyType kFloat{"float", ScalarType::float32, 4, true};
  a.values = s.reals(s.binary() ? kByte : kFloat, sec.n_tuples * static_cast<std::size_t>(n_comp),
                     "color values");
  if (s.binary())
    for (double& v : a.values) v /= 255.0;
  add_array(s, data, sec, std::move(a));
}

// A stand-alone LOOKUP_TABLE section: size RGBA entries, floats (ASCII) or bytes (binary).
void skip_lookup_table(LegacyScanner& s) {
  s.expect_token("a lookup table name");
  const auto n = static_cast<std::size_t>(s.integer("a lookup table size", 0, INT32_MAX));
  static constexpr LegacyType kByte{"unsigned_char", ScalarType::uint8, 1, false};
  static constexpr LegacyType kFloat{"float", ScalarType::float32, 4, true};
  s.reals(s.binary() ? kByte : kFloat, 4 * n, "lookup table values");
}

// One array of a FIELD block: "name n_comp n_tuples type" then the values. Returns false
// (after skipping it) for string arrays and null arrays, which carry no numbers.
bool read_field_array(LegacyScanner& s, DataArray& a, std::string* text) {
  const std::string_view first = s.expect_token("a field array name");
  if (keyword_is(first, "NULL_ARRAY")) return false;
  a.name = decode_name(first);
  a.n_components = static_cast<int>(s.integer("a number of components", 1, 1 << 20));
  const auto n_tuples = static_cast<std::size_t>(s.integer("a number of tuples", 0, INT32_MAX));
  const std::size_t n = n_tuples * static_cast<std::size_t>(a.n_components);
  if (keyword_is(s.peek_token(), "string") || keyword_is(s.peek_token(), "utf8_string")) {
    s.token();
    std::string first_value = s.strings(n);
    if (text) *text = std::move(first_value);
    return false;
  }
  const LegacyType& t = s.data_type();
  a.type = t.type;
  a.values = s.reals(t, n, "field values");
  return true;
}

void skip_metadata(LegacyScanner& s) {
  while (keyword_is(s.peek_token(), "METADATA")) {
    s.token();
    s.skip_block();
  }
}

void read_field(LegacyScanner& s, MeshData& data, const Section& sec) {
  s.expect_token("a field name");
  const auto n_arrays = s.integer("a number of arrays", 0, 1 << 20);
  for (std::int64_t k = 0; k < n_arrays; ++k) {
    const std::size_t at = s.mark();
    DataArray a;
    if (read_field_array(s, a, nullptr)) {
      if (a.n_tuples() != sec.n_tuples ||
          a.values.size() != sec.n_tuples * static_cast<std::size_t>(a.n_components))
        s.fail_at(at, "field array " + quote_token(a.name) + " has " +
                          std::to_string(a.n_tuples()) + " tuples, expected " +
                          std::to_string(sec.n_tuples));
      add_array(s, data, sec, std::move(a));
    }
    skip_metadata(s);
  }
}

void read_section_start(LegacyScanner& s, MeshData& data, Section& sec, bool cells) {
  const std::size_t expected =
      cells ? static_cast<std::size_t>(data.n_cells()) : data.points.size();
  const std::size_t at = s.mark();
  sec.cells = cells;
  sec.n_tuples = static_cast<std::size_t>(s.integer("a number of tuples", 0, INT64_MAX));
  if (sec.n_tuples != expected)
    s.fail_at(at, std::string(cells ? "CELL_DATA" : "POINT_DATA") + " " +
                      std::to_string(sec.n_tuples) + " does not match the " +
                      std::to_string(expected) + (cells ? " cells" : " points") +
                      " of the data set");
}

// Our `hexadapt_command` or `hexadapt_metadata`: text as a one-component char array.
bool is_text(const DataArray& a, const char* key) {
  return a.name == key && a.n_components == 1 &&
         (a.type == ScalarType::int8 || a.type == ScalarType::uint8);
}

std::string text_of(const DataArray& a) {
  std::string text;
  for (double v : a.values) text += static_cast<char>(static_cast<int>(v));
  return text;
}

}  // namespace

void read_attributes(LegacyScanner& s, MeshData& data) {
  Section sec;
  bool started = false;
  while (!s.at_end()) {
    const std::size_t at = s.mark();
    const std::string_view key = s.token();
    if (keyword_is(key, "CELL_DATA") || keyword_is(key, "POINT_DATA")) {
      read_section_start(s, data, sec, keyword_is(key, "CELL_DATA"));
      started = true;
      continue;
    }
    if (!started) s.fail_at(at, "expected CELL_DATA or POINT_DATA, found " + quote_token(key));
    if (keyword_is(key, "SCALARS")) {
      read_scalars(s, data, sec);
    } else if (keyword_is(key, "VECTORS") || keyword_is(key, "NORMALS")) {
      std::string name = decode_name(s.expect_token("an array name"));
      add_array(s, data, sec, read_array(s, sec, std::move(name), 3));
    } else if (keyword_is(key, "TENSORS") || keyword_is(key, "TENSORS6")) {
      std::string name = decode_name(s.expect_token("an array name"));
      add_array(s, data, sec,
                read_array(s, sec, std::move(name), keyword_is(key, "TENSORS") ? 9 : 6));
    } else if (keyword_is(key, "TEXTURE_COORDINATES")) {
      std::string name = decode_name(s.expect_token("an array name"));
      const int dim = static_cast<int>(s.integer("a texture dimension", 1, 3));
      add_array(s, data, sec, read_array(s, sec, std::move(name), dim));
    } else if (keyword_is(key, "GLOBAL_IDS") || keyword_is(key, "PEDIGREE_IDS")) {
      std::string name = decode_name(s.expect_token("an array name"));
      add_array(s, data, sec, read_array(s, sec, std::move(name), 1));
    } else if (keyword_is(key, "COLOR_SCALARS")) {
      read_color_scalars(s, data, sec);
    } else if (keyword_is(key, "LOOKUP_TABLE")) {
      skip_lookup_table(s);
    } else if (keyword_is(key, "FIELD")) {
      read_field(s, data, sec);
    } else if (keyword_is(key, "METADATA")) {
      s.skip_block();
    } else {
      s.fail_at(at, "unknown keyword " + quote_token(key) +
                        " in a data section (expected SCALARS, VECTORS, NORMALS, TENSORS, "
                        "FIELD, CELL_DATA or POINT_DATA)");
    }
  }
}

void read_dataset_field(LegacyScanner& s, MeshData& data) {
  s.expect_token("a field name");
  const auto n_arrays = s.integer("a number of arrays", 0, 1 << 20);
  Metadata found;
  std::optional<Metadata> whole;
  for (std::int64_t k = 0; k < n_arrays; ++k) {
    DataArray a;
    std::string text;
    if (!read_field_array(s, a, &text)) {
      if (!a.name.empty()) found.emplace_back(a.name, text);
    } else if (is_text(a, command_key)) {
      found.emplace_back(a.name, text_of(a));
    } else if (is_text(a, metadata_key)) {
      whole = parse_metadata_comment(text_of(a));  // not ours when it does not parse
      if (!whole) found.emplace_back(a.name, text_of(a));
    }
    skip_metadata(s);
  }
  if (whole) {  // every entry, the command and the title's pairs among them
    data.metadata.erase(std::remove_if(data.metadata.begin(), data.metadata.end(),
                                       [](const auto& e) { return e.first == "title"; }),
                        data.metadata.end());
    found.erase(std::remove_if(found.begin(), found.end(),
                               [](const auto& e) { return e.first == command_key; }),
                found.end());
    found.insert(found.begin(), whole->begin(), whole->end());
  }
  data.metadata.insert(data.metadata.end(), found.begin(), found.end());
}

}  // namespace hexadapt::io::detail
