// Private to the Exodus II reader: how many bytes a classic netCDF file (the container of
// Exodus II files: CDF-1, CDF-2 "64-bit offset", CDF-5) needs for the data its header
// declares. The netCDF library reads the missing tail of a truncated file as zeros, without
// an error; comparing this size with the file's catches the truncation.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace hexadapt::io::detail {

/// The end of the last variable's data (records included) declared by the classic netCDF
/// header at the start of `bytes` (the file's first bytes; the header must be complete in
/// them). Nothing when the bytes do not start with a classic header that parses (a netCDF-4
/// / HDF5 file, garbage, a header cut short): the netCDF library then judges the file.
std::optional<std::uint64_t> netcdf_data_end(std::string_view bytes);

}  // namespace hexadapt::io::detail
