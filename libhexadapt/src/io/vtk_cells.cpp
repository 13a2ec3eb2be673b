#include "vtk_cells.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/core/log.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::io::detail {

namespace {

// Maps 2D coordinates (axes a, b of the file) to x, y; the third coordinate is kept in z.
void map_plane(std::vector<Vec3>& points, int a, int b) {
  if (a == 0 && b == 1) return;
  const int c = 3 - a - b;
  for (Vec3& p : points) p = Vec3(p[a], p[b], p[c]);
}

Plane plane_of(int flat_axis) {
  return flat_axis == 2 ? Plane::xy : flat_axis == 0 ? Plane::yz : Plane::xz;
}

std::array<int, 2> plane_axes(Plane p) {
  switch (p) {
    case Plane::yz:
      return {1, 2};
    case Plane::xz:
      return {0, 2};
    default:
      return {0, 1};
  }
}

double signed_area(const MeshData& d, std::size_t c) {
  const Vec3& p0 = d.points[d.cells[4 * c].idx()];
  const Vec3& p1 = d.points[d.cells[4 * c + 1].idx()];
  const Vec3& p2 = d.points[d.cells[4 * c + 2].idx()];
  const Vec3& p3 = d.points[d.cells[4 * c + 3].idx()];
  return 0.5 * ((p2.x() - p0.x()) * (p3.y() - p1.y()) - (p3.x() - p1.x()) * (p2.y() - p0.y()));
}

// Every reader's points pass here: a NaN or infinite coordinate is refused with its point
// number (it would only surface later as a quality failure far from its cause).
void check_finite(const std::vector<Vec3>& points, const std::string& file) {
  for (std::size_t p = 0; p < points.size(); ++p)
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(points[p][a])) {
        std::ostringstream value;
        value << points[p][a];
        throw InputError(file, "point " + std::to_string(p),
                         std::string("coordinate ") + "xyz"[a] + " is " + value.str() +
                             ": coordinates must be finite numbers");
      }
}

}  // namespace

void fill_structured(MeshData& data, std::array<std::int64_t, 3> dims, std::vector<Vec3> points,
                     const ReadOptions& options, const std::string& file) {
  for (std::int64_t d : dims)
    if (d < 1)
      throw InputError(file, "DIMENSIONS", "a structured data set needs >= 1 point per axis");
  const std::int64_t n = dims[0] * dims[1] * dims[2];
  if (n > std::numeric_limits<index_t>::max())
    throw InputError(file, "DIMENSIONS", "too many points for 32-bit ids");
  if (static_cast<std::int64_t>(points.size()) != n)
    throw InputError(
        file, "points",
        "expected " + std::to_string(n) + " points, found " + std::to_string(points.size()));
  check_finite(points, file);
  const int flat = static_cast<int>(std::count(dims.begin(), dims.end(), 1));
  if (flat >= 2)
    throw InputError(file, "DIMENSIONS",
                     "a structured data set with a single row of points has "
                     "no quads or hexes");
  data.points = std::move(points);
  if (flat == 0) {
    data.dim = 3;
    append_structured_cells(static_cast<int>(dims[0] - 1), static_cast<int>(dims[1] - 1),
                            static_cast<int>(dims[2] - 1), data.cells);
    data.structured_cells = {static_cast<int>(dims[0] - 1), static_cast<int>(dims[1] - 1),
                             static_cast<int>(dims[2] - 1)};
    return;
  }
  const int flat_axis = static_cast<int>(std::find(dims.begin(), dims.end(), 1) - dims.begin());
  const Plane given = options.plane == Plane::automatic ? plane_of(flat_axis) : options.plane;
  if (given != plane_of(flat_axis))
    throw InputError(file, "DIMENSIONS",
                     "the data set is flat along axis " + std::to_string(flat_axis) +
                         ", not in the requested plane");
  const auto ax = plane_axes(given);
  if (ax[0] != 0 || ax[1] != 1)
    log_info(file + ": 2D data set in a coordinate plane other than xy: mapped to xy");
  map_plane(data.points, ax[0], ax[1]);
  const int nx = static_cast<int>(dims[static_cast<std::size_t>(ax[0])] - 1);
  const int ny = static_cast<int>(dims[static_cast<std::size_t>(ax[1])] - 1);
  data.dim = 2;
  append_structured_cells(nx, ny, 0, data.cells);
  data.structured_cells = {nx, ny, 0};
}

void append_vtk_cell(MeshData& data, int type, const std::int64_t* ids, std::size_t n_ids,
                     std::int64_t cell, const std::string& file) {
  const std::string where = "cell " + std::to_string(cell);
  int dim;
  std::size_t expected;
  switch (type) {
    case vtk_pixel:
    case vtk_quad:
      dim = 2;
      expected = 4;
      break;
    case vtk_voxel:
    case vtk_hexahedron:
      dim = 3;
      expected = 8;
      break;
    default:
      throw InputError(file, where,
                       "unsupported VTK cell type " + std::to_string(type) +
                           " (only quads, pixels, hexahedra and voxels)");
  }
  if (n_ids != expected)
    throw InputError(file, where,
                     "cell type " + std::to_string(type) + " has " + std::to_string(n_ids) +
                         " nodes, expected " + std::to_string(expected));
  if (data.dim != 0 && data.dim != dim)
    throw InputError(file, where, "mixes 2D and 3D cells: a mesh holds quads or hexes, not both");
  data.dim = dim;
  for (std::size_t k = 0; k < n_ids; ++k)
    if (ids[k] < 0 || ids[k] >= static_cast<std::int64_t>(data.points.size()))
      throw InputError(file, where,
                       "node id " + std::to_string(ids[k]) + " out of range [0, " +
                           std::to_string(data.points.size()) + ")");
  auto id = [&](int k) { return NodeId(ids[k]); };
  switch (type) {
    case vtk_pixel:
      data.cells.insert(data.cells.end(), {id(0), id(1), id(3), id(2)});
      break;
    case vtk_quad:
      data.cells.insert(data.cells.end(), {id(0), id(1), id(2), id(3)});
      break;
    case vtk_voxel:
      for (int k = 0; k < 8; ++k) data.cells.push_back(id(k));
      break;
    default:
      for (int b = 0; b < 8; ++b)
        data.cells.push_back(id(ref_hex::vtk_of_binary[static_cast<std::size_t>(b)]));
  }
}

void finish_unstructured(MeshData& data, const ReadOptions& options, const std::string& file) {
  check_finite(data.points, file);
  if (data.dim != 2) return;
  Plane plane = options.plane;
  if (plane == Plane::automatic) {
    // The coordinate along which every point has the same value is the flat one; z first.
    plane = Plane::xy;
    for (int axis : {2, 0, 1}) {
      const bool constant = std::all_of(data.points.begin(), data.points.end(), [&](const Vec3& p) {
        return p[axis] == data.points.front()[axis];
      });
      if (constant) {
        plane = plane_of(axis);
        break;
      }
    }
  }
  const auto ax = plane_axes(plane);
  const int c = 3 - ax[0] - ax[1];
  double lo = 0, hi = 0;
  if (!data.points.empty()) {
    lo = hi = data.points.front()[c];
    for (const Vec3& p : data.points) lo = std::min(lo, p[c]), hi = std::max(hi, p[c]);
  }
  double extent = 0;
  for (const Vec3& p : data.points) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  if (hi - lo > 1e-9 * std::max(1.0, extent))
    throw InputError(file, "points",
                     "quads are not in one coordinate plane (the third "
                     "coordinate varies by " +
                         std::to_string(hi - lo) + "); give the plane explicitly");
  map_plane(data.points, ax[0], ax[1]);
  const std::size_t n = static_cast<std::size_t>(data.n_cells());
  std::size_t clockwise = 0;
  for (std::size_t k = 0; k < n; ++k) clockwise += signed_area(data, k) < 0;
  if (2 * clockwise > n) {
    log_info(file + ": quads listed clockwise in the plane: reoriented counter-clockwise");
    for (std::size_t k = 0; k < n; ++k) std::swap(data.cells[4 * k + 1], data.cells[4 * k + 3]);
  }
}

}  // namespace hexadapt::io::detail
