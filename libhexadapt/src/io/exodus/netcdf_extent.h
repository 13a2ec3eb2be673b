// Private to the Exodus II reader: a bounds-checked walk through the header of a classic
// netCDF file (the container of Exodus II files: CDF-1, CDF-2 "64-bit offset", CDF-5), done
// before the netCDF library sees the file, and how many bytes the data it declares needs.
// Both guard against what the library does with hostile files: it allocates a name length
// read from the header before checking it against the file (a 5 kB file asked for 2.8 GB),
// and it reads the missing tail of a truncated file as zeros, without an error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hexadapt::io::detail {

struct NetcdfHeader {
  bool classic = false;        ///< the bytes start with "CDF" and a version of the classic format
  bool complete = false;       ///< the header parsed whole within the bytes, every count in bounds
  std::uint64_t data_end = 0;  ///< end of the last variable's data, records included
  /// Name and number of values of each global attribute.
  std::vector<std::pair<std::string, std::uint64_t>> global_attributes;
};

/// Walks the classic netCDF header at the start of `bytes` (the file's first bytes). A count
/// or length that runs past the bytes leaves `complete` false.
NetcdfHeader netcdf_header(std::string_view bytes);

}  // namespace hexadapt::io::detail
