// Private to the VTK XML reader and writer: VTK's scalar type names and the conversion of
// packed binary values (either byte order) to and from doubles and 64-bit integers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "hexadapt/core/parallel.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io::detail {

/// The type named by a DataArray's `type` attribute ("Float64", "Int32", ...), if numeric.
std::optional<ScalarType> scalar_type_of(std::string_view vtk_name);
/// VTK's name of a type.
const char* vtk_name(ScalarType t);
std::size_t scalar_size(ScalarType t);
bool is_integer(ScalarType t);

/// True on little-endian machines (what the writer declares as byte_order).
bool native_little_endian();

/// Converts n packed values of type t (byte-swapped when `swap`) to doubles.
void unpack(const unsigned char* src, ScalarType t, bool swap, std::size_t n, double* out);
/// Converts n packed integer values to int64. Returns the index of the first value that does
/// not fit (an UInt64 above INT64_MAX or a non-integral float), or n when all fit.
std::size_t unpack(const unsigned char* src, ScalarType t, bool swap, std::size_t n,
                   std::int64_t* out);

/// Runs f(b) for the n zlib blocks of an array, on threads only when there are a few blocks
/// or more (a parallel region costs more than one block).
template <class F>
void for_blocks(std::int64_t n, F&& f) {
  if (n < 8) {
    for (std::int64_t b = 0; b < n; ++b) f(b);
  } else {
    parallel_for(n, f);
  }
}

/// Packs n doubles as type t in native byte order; integer types are rounded to nearest and
/// clamped to the type's range (NaN becomes 0).
void pack(const double* values, std::size_t n, ScalarType t, unsigned char* out);

}  // namespace hexadapt::io::detail
