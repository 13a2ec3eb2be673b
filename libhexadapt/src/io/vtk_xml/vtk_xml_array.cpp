#include "vtk_xml_array.h"

#include <limits>

#include "hexadapt/core/error.h"
#include "vtk_xml_scalar.h"

namespace hexadapt::io::detail {

namespace {

struct Text {
  std::string_view value;
  std::size_t offset = 0;  ///< file offset of value[0]
};

// The character data of an element and its file offset (of the element when empty).
Text element_text(const pugi::xml_node& e) {
  for (pugi::xml_node c = e.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata)
      return {c.value(), static_cast<std::size_t>(std::max<std::ptrdiff_t>(c.offset_debug(), 0))};
  return {"", static_cast<std::size_t>(std::max<std::ptrdiff_t>(e.offset_debug(), 0))};
}

ScalarType type_of(const VtkXmlDocument& doc, const pugi::xml_node& e) {
  const std::string name = e.attribute("type").as_string();
  const auto t = scalar_type_of(name);
  if (!t)
    throw InputError(doc.file, place(e),
                     "unknown or unsupported data type " + quote_token(name) +
                         " (expected Int8..UInt64, Float32 or Float64)");
  return *t;
}

// A reader positioned at the binary payload of e (inline base64 or appended).
ByteReader payload_reader(const VtkXmlDocument& doc, const pugi::xml_node& e,
                          const std::string& format) {
  if (format == "binary") {
    const Text t = element_text(e);
    return ByteReader::base64(t.value, t.offset, doc.file);
  }
  if (!doc.has_appended)
    throw InputError(doc.file, place(e), "format=\"appended\" but the file has no AppendedData");
  const std::uint64_t offset = count_attribute(doc, e, "offset");
  if (offset > doc.appended.size())
    throw InputError(doc.file, place(e),
                     "offset " + std::to_string(offset) +
                         " is beyond the end of the appended data (" +
                         std::to_string(doc.appended.size()) + " bytes; truncated file?)");
  const auto at = static_cast<std::size_t>(offset);
  const std::string_view rest = doc.appended.substr(at);
  return doc.appended_base64 ? ByteReader::base64(rest, doc.appended_offset + at, doc.file)
                             : ByteReader::raw(rest, doc.appended_offset + at, doc.file);
}

std::string format_of(const VtkXmlDocument& doc, const pugi::xml_node& e) {
  const std::string f = e.attribute("format").as_string("ascii");
  if (f != "ascii" && f != "binary" && f != "appended")
    throw InputError(doc.file, place(e),
                     "format " + quote_token(f) + ": expected ascii, binary or appended");
  return f;
}

template <class T>
std::vector<T> read_values(const VtkXmlDocument& doc, const pugi::xml_node& e, ScalarType t,
                           std::size_t n) {
  const std::string what = place(e);
  const std::string format = format_of(doc, e);
  if (n > std::numeric_limits<std::size_t>::max() / 16)
    throw InputError(doc.file, what, "implausible number of values " + std::to_string(n));
  if (format == "ascii") {
    const Text text = element_text(e);
    // Each value takes at least one character and a separator: check before allocating.
    if (n > text.value.size() / 2 + 1)
      throw InputError(doc.file, what,
                       "expected " + std::to_string(n) + " values, found " +
                           std::to_string(count_tokens(text.value)));
    std::vector<T> out(n);
    parse_ascii(text.value, text.offset, t, n, out.data(), doc.file, what);
    return out;
  }
  ByteReader in = payload_reader(doc, e, format);
  const bool swap = doc.layout.big_endian == native_little_endian();
  // Doubles in native order need no conversion: compressed blocks decompress straight
  // into the result.
  const bool direct = std::is_same_v<T, double> && t == ScalarType::float64 && !swap;
  std::vector<T> out;
  if (direct && doc.layout.compressor != Compressor::none) {
    read_payload(in, doc.layout, n * scalar_size(t), what, [&](std::size_t) {
      out.resize(n);
      return reinterpret_cast<unsigned char*>(out.data());
    });
    return out;
  }
  const Payload p = read_payload(in, doc.layout, n * scalar_size(t), what);
  out.resize(n);
  if constexpr (std::is_same_v<T, double>) {
    unpack(p.data, t, swap, n, out.data());
  } else {
    const std::size_t bad = unpack(p.data, t, swap, n, out.data());
    if (bad < n)
      throw InputError(doc.file, what,
                       "value " + std::to_string(bad) + " is not an integer that fits in 64 bits");
  }
  return out;
}

}  // namespace

DataArray read_data_array(const VtkXmlDocument& doc, const pugi::xml_node& e, std::size_t n_tuples,
                          int components) {
  DataArray a;
  a.name = e.attribute("Name").as_string();
  a.type = type_of(doc, e);
  const std::uint64_t nc =
      e.attribute("NumberOfComponents") ? count_attribute(doc, e, "NumberOfComponents") : 1;
  if (nc < 1 || nc > 1024)
    throw InputError(doc.file, place(e),
                     "NumberOfComponents " + std::to_string(nc) + ": expected 1 to 1024");
  a.n_components = static_cast<int>(nc);
  if (components > 0 && a.n_components != components)
    throw InputError(
        doc.file, place(e),
        "expected " + std::to_string(components) + " components, found " + std::to_string(nc));
  if (n_tuples > std::numeric_limits<std::size_t>::max() / 1024)
    throw InputError(doc.file, place(e), "implausible number of tuples");
  a.values = read_values<double>(doc, e, a.type, n_tuples * static_cast<std::size_t>(nc));
  return a;
}

std::vector<std::int64_t> read_int_array(const VtkXmlDocument& doc, const pugi::xml_node& e,
                                         std::size_t n) {
  const ScalarType t = type_of(doc, e);
  return read_values<std::int64_t>(doc, e, t, n);
}

std::vector<std::string> read_string_array(const VtkXmlDocument& doc, const pugi::xml_node& e) {
  std::vector<unsigned char> bytes;
  const std::string format = format_of(doc, e);
  if (format == "ascii") {
    const Text text = element_text(e);
    std::vector<std::int64_t> codes(count_tokens(text.value));
    parse_ascii(text.value, text.offset, ScalarType::uint8, codes.size(), codes.data(), doc.file,
                place(e));
    for (std::int64_t c : codes) {
      if (c < 0 || c > 255) throw InputError(doc.file, place(e), "character code out of 0..255");
      bytes.push_back(static_cast<unsigned char>(c));
    }
  } else {
    ByteReader in = payload_reader(doc, e, format);
    const Payload p = read_payload(in, doc.layout, std::nullopt, place(e));
    bytes.assign(p.data, p.data + p.size);
  }
  std::vector<std::string> strings;
  std::string current;
  for (unsigned char b : bytes) {
    if (b == 0) {
      strings.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(b);
    }
  }
  if (!current.empty()) strings.push_back(current);
  return strings;
}

}  // namespace hexadapt::io::detail
