#include "vtk_xml_scalar.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace hexadapt::io::detail {

namespace {

struct TypeName {
  ScalarType type;
  const char* name;
};
constexpr std::array<TypeName, 10> names = {{{ScalarType::int8, "Int8"},
                                             {ScalarType::uint8, "UInt8"},
                                             {ScalarType::int16, "Int16"},
                                             {ScalarType::uint16, "UInt16"},
                                             {ScalarType::int32, "Int32"},
                                             {ScalarType::uint32, "UInt32"},
                                             {ScalarType::int64, "Int64"},
                                             {ScalarType::uint64, "UInt64"},
                                             {ScalarType::float32, "Float32"},
                                             {ScalarType::float64, "Float64"}}};

template <class T>
T load(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

// Calls f(T{}) with T the C++ type of t.
template <class F>
decltype(auto) visit_type(ScalarType t, F&& f) {
  switch (t) {
    case ScalarType::int8:
      return f(std::int8_t{});
    case ScalarType::uint8:
      return f(std::uint8_t{});
    case ScalarType::int16:
      return f(std::int16_t{});
    case ScalarType::uint16:
      return f(std::uint16_t{});
    case ScalarType::int32:
      return f(std::int32_t{});
    case ScalarType::uint32:
      return f(std::uint32_t{});
    case ScalarType::int64:
      return f(std::int64_t{});
    case ScalarType::uint64:
      return f(std::uint64_t{});
    case ScalarType::float32:
      return f(float{});
    default:
      return f(double{});
  }
}

template <class T>
T to_integer(double v) {
  if (std::isnan(v)) return T{0};
  const double r = std::nearbyint(v);
  // The largest values of 64-bit types are not doubles; compare against their next double.
  if (r <= static_cast<double>(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
  if (r >= static_cast<double>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
  return static_cast<T>(r);
}

}  // namespace

std::optional<ScalarType> scalar_type_of(std::string_view vtk_name_) {
  for (const auto& n : names)
    if (vtk_name_ == n.name) return n.type;
  // Names of VTK files older than 2006, still accepted by VTK.
  if (vtk_name_ == "Char") return ScalarType::int8;
  return std::nullopt;
}

const char* vtk_name(ScalarType t) {
  return names[static_cast<std::size_t>(t)].name;
}

std::size_t scalar_size(ScalarType t) {
  return visit_type(t, [](auto v) { return sizeof(v); });
}

bool is_integer(ScalarType t) {
  return t != ScalarType::float32 && t != ScalarType::float64;
}

bool native_little_endian() {
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

void unpack(const unsigned char* src, ScalarType t, bool swap, std::size_t n, double* out) {
  if (n == 0) return;
  if (t == ScalarType::float64 && !swap) {
    std::memcpy(out, src, n * sizeof(double));
    return;
  }
  visit_type(t, [&](auto zero) {
    using T = decltype(zero);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = static_cast<double>(load<T>(src + i * sizeof(T), swap));
  });
}

std::size_t unpack(const unsigned char* src, ScalarType t, bool swap, std::size_t n,
                   std::int64_t* out) {
  return visit_type(t, [&](auto zero) -> std::size_t {
    using T = decltype(zero);
    for (std::size_t i = 0; i < n; ++i) {
      const T v = load<T>(src + i * sizeof(T), swap);
      if constexpr (std::is_floating_point_v<T>) {
        const auto d = static_cast<double>(v);
        if (!(std::nearbyint(d) == d) || std::fabs(d) > 9.0e15) return i;
        out[i] = static_cast<std::int64_t>(d);
      } else if constexpr (std::is_same_v<T, std::uint64_t>) {
        if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return i;
        out[i] = static_cast<std::int64_t>(v);
      } else {
        out[i] = static_cast<std::int64_t>(v);
      }
    }
    return n;
  });
}

void pack(const double* values, std::size_t n, ScalarType t, unsigned char* out) {
  if (n == 0) return;
  if (t == ScalarType::float64) {
    std::memcpy(out, values, n * sizeof(double));
    return;
  }
  visit_type(t, [&](auto zero) {
    using T = decltype(zero);
    for (std::size_t i = 0; i < n; ++i) {
      T v;
      if constexpr (std::is_floating_point_v<T>)
        v = static_cast<T>(values[i]);
      else
        v = to_integer<T>(values[i]);
      std::memcpy(out + i * sizeof(T), &v, sizeof(T));
    }
  });
}

}  // namespace hexadapt::io::detail
