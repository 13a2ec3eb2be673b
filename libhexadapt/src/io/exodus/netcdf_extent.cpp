// The classic netCDF header, as the format specification lays it out (big-endian):
//   magic "CDF" version, numrecs, dim_list, gatt_list, var_list
//   var = name, dimids, vatt_list, nc_type, vsize, begin
// Only what locates the data is kept; every count is checked against the bytes left.
#include "netcdf_extent.h"

#include <algorithm>
#include <vector>

namespace hexadapt::io::detail {

namespace {

constexpr std::uint32_t tag_dimension = 0x0A, tag_variable = 0x0B, tag_attribute = 0x0C;

struct Header {
  std::string_view bytes;
  std::size_t at = 0;
  int version = 1;  // 1, 2 (64-bit offsets) or 5 (64-bit sizes)
  bool ok = true;

  std::uint64_t word(std::size_t n) {
    if (!ok || bytes.size() - at < n) {
      ok = false;
      return 0;
    }
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < n; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    at += n;
    return v;
  }
  std::uint64_t count() { return word(version == 5 ? 8 : 4); }
  void skip(std::uint64_t n) {
    if (!ok || bytes.size() - at < n) {
      ok = false;
      return;
    }
    at += static_cast<std::size_t>(n);
  }
  void skip_padded(std::uint64_t n) { skip(n + ((4 - n % 4) % 4)); }
  void skip_name() { skip_padded(count()); }
  // A list header: its tag (or ABSENT, 0) and its length.
  std::uint64_t list(std::uint32_t tag) {
    const std::uint64_t t = word(4);
    const std::uint64_t n = count();
    if (t != tag && !(t == 0 && n == 0)) ok = false;
    if (n > bytes.size()) ok = false;  // each entry takes at least one byte
    return ok ? n : 0;
  }
};

std::uint64_t type_size(std::uint64_t type) {
  switch (type) {
    case 1:
    case 2:
    case 7:
      return 1;  // byte, char, ubyte
    case 3:
    case 8:
      return 2;  // short, ushort
    case 4:
    case 5:
    case 9:
      return 4;  // int, float, uint
    case 6:
    case 10:
    case 11:
      return 8;  // double, int64, uint64
    default:
      return 0;
  }
}

// The types of the format's version: CDF-5 adds the unsigned and 64-bit ones. Anything
// else (a netCDF-4 string, type 12) gets a size of 0, on which the library divides by zero.
std::uint64_t checked_type_size(Header& h) {
  const std::uint64_t type = h.word(4);
  const std::uint64_t size = type <= (h.version == 5 ? 11u : 6u) ? type_size(type) : 0;
  if (size == 0) h.ok = false;
  return size;
}

void skip_attributes(Header& h, std::vector<std::pair<std::string, std::uint64_t>>* out = nullptr) {
  const std::uint64_t n = h.list(tag_attribute);
  for (std::uint64_t k = 0; k < n && h.ok; ++k) {
    const std::uint64_t length = h.count();  // the name's bytes, without the padding
    const std::size_t name_at = h.at;
    h.skip_padded(length);
    const std::string name(h.ok ? h.bytes.substr(name_at, static_cast<std::size_t>(length))
                                : std::string_view());
    const std::uint64_t size = checked_type_size(h);
    const std::uint64_t values = h.count();
    if (size == 0 || values > h.bytes.size()) h.ok = false;
    if (out != nullptr && h.ok) out->emplace_back(name, values);
    h.skip_padded(size * values);
  }
}

}  // namespace

NetcdfHeader netcdf_header(std::string_view bytes) {
  NetcdfHeader out;
  Header h{bytes};
  if (bytes.size() < 4 || bytes.substr(0, 3) != "CDF") return out;
  h.version = static_cast<unsigned char>(bytes[3]);
  if (h.version != 1 && h.version != 2 && h.version != 5) return out;
  out.classic = true;
  h.at = 4;
  const std::uint64_t numrecs = h.count();
  std::vector<std::uint64_t> lengths;  // 0: the unlimited dimension
  const std::uint64_t n_dims = h.list(tag_dimension);
  for (std::uint64_t k = 0; k < n_dims && h.ok; ++k) {
    h.skip_name();
    lengths.push_back(h.count());
  }
  skip_attributes(h, &out.global_attributes);
  struct Var {
    bool record;
    std::uint64_t vsize, begin;
  };
  std::vector<Var> vars;
  const std::uint64_t n_vars = h.list(tag_variable);
  for (std::uint64_t k = 0; k < n_vars && h.ok; ++k) {
    h.skip_name();
    const std::uint64_t rank = h.count();
    if (rank > bytes.size()) h.ok = false;
    bool record = false;
    // The library sizes a variable by its dimensions (the header's vsize is only a hint):
    // so do we, refusing products past 2^62.
    std::uint64_t values = 1;
    const std::uint64_t limit = std::uint64_t(1) << 62;
    for (std::uint64_t d = 0; d < rank && h.ok; ++d) {
      const std::uint64_t id = h.count();
      if (id >= lengths.size()) h.ok = false;
      if (!h.ok) break;
      const std::uint64_t len = lengths[static_cast<std::size_t>(id)];
      // The unlimited dimension may only come first: the library divides by a later one.
      if (len == 0) {
        if (d > 0) h.ok = false;
        record = true;
      } else if (values > limit / len) {
        h.ok = false;
      } else {
        values *= len;
      }
    }
    skip_attributes(h);
    const std::uint64_t size = checked_type_size(h);
    h.count();  // vsize
    const std::uint64_t begin = h.word(h.version == 1 ? 4 : 8);
    if (h.ok && values > limit / 8) h.ok = false;
    const std::uint64_t bytes_used = values * size;
    vars.push_back({record, bytes_used + (4 - bytes_used % 4) % 4, begin});
  }
  if (!h.ok) return out;
  // numrecs of all ones: a file written in streaming mode, its record count unknown.
  const bool streaming = numrecs == (h.version == 5 ? ~std::uint64_t(0) : 0xFFFFFFFFu);
  std::uint64_t record_size = 0;
  int n_record_vars = 0;
  for (const Var& v : vars)
    if (v.record) {
      record_size += v.vsize;
      ++n_record_vars;
    }
  std::uint64_t end = h.at;
  const std::uint64_t limit = std::uint64_t(1) << 62;  // no real file; keeps the sums exact
  for (const Var& v : vars) {
    if (v.begin > limit || v.vsize > limit || record_size > limit) return out;
    std::uint64_t last = v.begin + v.vsize;
    if (v.record) {
      if (streaming || numrecs == 0) continue;
      if (numrecs - 1 > limit / std::max<std::uint64_t>(record_size, 1)) return out;
      // A lone record variable's records are not padded to 4 bytes as its vsize is: count
      // its full records only, a bound that holds either way.
      last = v.begin + (numrecs - 1) * record_size + (n_record_vars == 1 ? 0 : v.vsize);
    }
    end = std::max(end, last);
  }
  out.complete = true;
  out.data_end = end;
  return out;
}

}  // namespace hexadapt::io::detail
