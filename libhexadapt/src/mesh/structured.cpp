#include "hexadapt/mesh/structured.h"

#include <algorithm>
#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt {

namespace {

void check_counts(std::initializer_list<int> n) {
  for (int v : n)
    if (v < 1) throw OptionError("a structured grid needs at least one cell per axis");
}

void check_axis(const std::vector<double>& c, char axis) {
  if (c.size() < 2)
    throw OptionError(std::string("rectilinear axis ") + axis + " needs at least 2 nodes");
  for (std::size_t i = 1; i < c.size(); ++i)
    if (!(c[i] > c[i - 1]))
      throw OptionError(std::string("rectilinear axis ") + axis +
                        " is not strictly increasing at node " + std::to_string(i));
}

std::vector<double> regular_axis(int n, double origin, double spacing) {
  std::vector<double> c(static_cast<std::size_t>(n) + 1);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = origin + spacing * static_cast<double>(i);
  return c;
}

NodeId node_id(int i, int j, int k, int nx, int ny) {
  return NodeId(static_cast<std::int64_t>(i) +
                static_cast<std::int64_t>(nx + 1) * (j + static_cast<std::int64_t>(ny + 1) * k));
}

}  // namespace

void append_structured_cells(int nx, int ny, int nz, std::vector<NodeId>& out) {
  if (nz == 0) {
    check_counts({nx, ny});
    out.reserve(out.size() + 4 * static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        out.insert(out.end(), {node_id(i, j, 0, nx, ny), node_id(i + 1, j, 0, nx, ny),
                               node_id(i + 1, j + 1, 0, nx, ny), node_id(i, j + 1, 0, nx, ny)});
    return;
  }
  check_counts({nx, ny, nz});
  out.reserve(out.size() + 8 * static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) *
                               static_cast<std::size_t>(nz));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (int v = 0; v < 8; ++v)
          out.push_back(node_id(i + (v & 1), j + ((v >> 1) & 1), k + ((v >> 2) & 1), nx, ny));
}

namespace {

template <std::size_t N>
std::vector<std::array<NodeId, N>> grouped(const std::vector<NodeId>& flat) {
  std::vector<std::array<NodeId, N>> cells(flat.size() / N);
  for (std::size_t c = 0; c < cells.size(); ++c)
    std::copy(flat.begin() + static_cast<std::ptrdiff_t>(N * c),
              flat.begin() + static_cast<std::ptrdiff_t>(N * (c + 1)), cells[c].begin());
  return cells;
}

}  // namespace

std::vector<std::array<NodeId, 4>> structured_quads(int nx, int ny) {
  std::vector<NodeId> flat;
  append_structured_cells(nx, ny, 0, flat);
  return grouped<4>(flat);
}

std::vector<std::array<NodeId, 8>> structured_hexes(int nx, int ny, int nz) {
  check_counts({nx, ny, nz});  // nz == 0 would ask append_structured_cells for quads
  std::vector<NodeId> flat;
  append_structured_cells(nx, ny, nz, flat);
  return grouped<8>(flat);
}

QuadMesh make_quad_grid(int nx, int ny, const Vec3& origin, const Vec3& spacing) {
  check_counts({nx, ny});
  std::vector<Vec3> pts;
  const auto xs = regular_axis(nx, origin.x(), spacing.x());
  const auto ys = regular_axis(ny, origin.y(), spacing.y());
  for (double y : ys)
    for (double x : xs) pts.emplace_back(x, y, origin.z());
  return QuadMesh(std::move(pts), structured_quads(nx, ny));
}

QuadMesh make_quad_grid(const std::vector<double>& xs, const std::vector<double>& ys) {
  check_axis(xs, 'x');
  check_axis(ys, 'y');
  std::vector<Vec3> pts;
  for (double y : ys)
    for (double x : xs) pts.emplace_back(x, y, 0.0);
  return QuadMesh(std::move(pts), structured_quads(static_cast<int>(xs.size()) - 1,
                                                   static_cast<int>(ys.size()) - 1));
}

QuadMesh make_quad_grid(int nx, int ny, std::vector<Vec3> points) {
  check_counts({nx, ny});
  if (points.size() != static_cast<std::size_t>(nx + 1) * static_cast<std::size_t>(ny + 1))
    throw OptionError("curvilinear grid: expected (nx+1)*(ny+1) points");
  return QuadMesh(std::move(points), structured_quads(nx, ny));
}

HexMesh make_hex_grid(int nx, int ny, int nz, const Vec3& origin, const Vec3& spacing) {
  check_counts({nx, ny, nz});
  return make_hex_grid(regular_axis(nx, origin.x(), spacing.x()),
                       regular_axis(ny, origin.y(), spacing.y()),
                       regular_axis(nz, origin.z(), spacing.z()));
}

HexMesh make_hex_grid(const std::vector<double>& xs, const std::vector<double>& ys,
                      const std::vector<double>& zs) {
  check_axis(xs, 'x');
  check_axis(ys, 'y');
  check_axis(zs, 'z');
  std::vector<Vec3> pts;
  pts.reserve(xs.size() * ys.size() * zs.size());
  for (double z : zs)
    for (double y : ys)
      for (double x : xs) pts.emplace_back(x, y, z);
  return HexMesh(std::move(pts),
                 structured_hexes(static_cast<int>(xs.size()) - 1, static_cast<int>(ys.size()) - 1,
                                  static_cast<int>(zs.size()) - 1));
}

HexMesh make_hex_grid(int nx, int ny, int nz, std::vector<Vec3> points) {
  check_counts({nx, ny, nz});
  if (points.size() != static_cast<std::size_t>(nx + 1) * static_cast<std::size_t>(ny + 1) *
                           static_cast<std::size_t>(nz + 1))
    throw OptionError("curvilinear grid: expected (nx+1)*(ny+1)*(nz+1) points");
  return HexMesh(std::move(points), structured_hexes(nx, ny, nz));
}

}  // namespace hexadapt
