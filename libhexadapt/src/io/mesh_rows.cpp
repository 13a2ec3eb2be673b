#include "mesh_rows.h"

#include <algorithm>

namespace hexadapt::io::detail {

int row_width(bool with_points, const std::vector<DataArray>& arrays) {
  int width = with_points ? 3 : 0;
  for (const DataArray& a : arrays) width += a.n_components;
  return width;
}

std::vector<double> rows_of(const std::vector<Vec3>* points, const std::vector<DataArray>& arrays,
                            std::size_t n) {
  std::vector<double> rows;
  rows.reserve(n * static_cast<std::size_t>(row_width(points != nullptr, arrays)));
  for (std::size_t i = 0; i < n; ++i) {
    if (points) rows.insert(rows.end(), (*points)[i].data(), (*points)[i].data() + 3);
    for (const DataArray& a : arrays) {
      const auto nc = static_cast<std::size_t>(a.n_components);
      rows.insert(rows.end(), a.values.begin() + static_cast<std::ptrdiff_t>(i * nc),
                  a.values.begin() + static_cast<std::ptrdiff_t>((i + 1) * nc));
    }
  }
  return rows;
}

void set_rows(const std::vector<double>& rows, std::size_t n, std::vector<Vec3>* points,
              std::vector<DataArray>& arrays) {
  const auto w = static_cast<std::size_t>(row_width(points != nullptr, arrays));
  std::size_t column = 0;
  if (points) {
    points->resize(n);
    for (std::size_t i = 0; i < n; ++i)
      (*points)[i] = Vec3(rows[i * w], rows[i * w + 1], rows[i * w + 2]);
    column = 3;
  }
  for (DataArray& a : arrays) {
    const auto nc = static_cast<std::size_t>(a.n_components);
    a.values.resize(n * nc);
    for (std::size_t i = 0; i < n; ++i)
      std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(i * w + column), nc,
                  a.values.begin() + static_cast<std::ptrdiff_t>(i * nc));
    column += nc;
  }
}

}  // namespace hexadapt::io::detail
