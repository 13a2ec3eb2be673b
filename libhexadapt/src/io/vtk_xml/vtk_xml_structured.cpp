// ImageData (.vti), RectilinearGrid (.vtr) and StructuredGrid (.vts): a block of points
// given by an extent; cells are implicit.
#include <cmath>
#include <sstream>

#include "../vtk_cells.h"
#include "hexadapt/core/error.h"
#include "vtk_xml_array.h"
#include "vtk_xml_reader.h"

namespace hexadapt::io::detail {

namespace {

template <std::size_t N>
std::array<double, N> numbers(const VtkXmlDocument& doc, const pugi::xml_node& e, const char* name,
                              std::array<double, N> fallback) {
  const pugi::xml_attribute a = e.attribute(name);
  if (!a) return fallback;
  std::array<double, N> v{};
  const std::string text = a.as_string();
  std::vector<double> parsed(N);
  parse_ascii(text, 0, ScalarType::float64, N, parsed.data(), doc.file,
              place(e) + " attribute " + name);
  std::copy(parsed.begin(), parsed.end(), v.begin());
  return v;
}

struct Block {
  std::array<std::int64_t, 6> extent{};
  std::array<std::int64_t, 3> dims{};
  std::size_t n_points = 1, n_cells = 1;
};

// The extent of the piece (or of the whole data set), its point and cell counts.
Block block_of(const VtkXmlDocument& doc, const pugi::xml_node& dataset,
               const pugi::xml_node& piece) {
  const pugi::xml_node e = piece.attribute("Extent") ? piece : dataset;
  const char* attr = piece.attribute("Extent") ? "Extent" : "WholeExtent";
  if (!e.attribute(attr)) throw InputError(doc.file, place(piece), "no Extent or WholeExtent");
  std::vector<std::int64_t> v(6);
  parse_ascii(e.attribute(attr).as_string(), 0, ScalarType::int64, 6, v.data(), doc.file,
              place(e) + " attribute " + attr);
  Block b;
  for (std::size_t a = 0; a < 3; ++a) {
    b.extent[2 * a] = v[2 * a];
    b.extent[2 * a + 1] = v[2 * a + 1];
    if (v[2 * a + 1] < v[2 * a] || v[2 * a + 1] - v[2 * a] >= std::numeric_limits<index_t>::max())
      throw InputError(doc.file, place(e),
                       std::string(attr) + " axis " + std::to_string(a) +
                           ": expected min <= max within 32-bit ids");
    b.dims[a] = v[2 * a + 1] - v[2 * a] + 1;
    b.n_points *= static_cast<std::size_t>(b.dims[a]);
    b.n_cells *= static_cast<std::size_t>(std::max<std::int64_t>(b.dims[a] - 1, 1));
    if (b.n_points > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
      throw InputError(doc.file, place(e), "too many points for 32-bit ids");
  }
  return b;
}

// A lattice (.vti, .vtr) is generated from its extent, not read: millions of points announced
// by a file without a single array for them and too small to hold one are a lie (or nothing
// to work on), refused before allocating (as the legacy reader does). Arrays that are present
// were already checked against the bytes that hold them.
void refuse_empty_lattice(const VtkXmlDocument& doc, const pugi::xml_node& piece, const Block& b,
                          const MeshData& data) {
  if (b.n_points <= (std::size_t{1} << 20) || b.n_points / 8 <= doc.size) return;
  if (!data.cell_data.empty() || !data.point_data.empty()) return;
  throw InputError(doc.file, place(piece),
                   "the extent announces " + std::to_string(b.n_points) + " points and " +
                       std::to_string(b.n_cells) +
                       " cells but the file has no point or cell array and only " +
                       std::to_string(doc.size) + " bytes");
}

template <class F>
void for_each_point(const Block& b, F&& f) {
  for (std::int64_t k = 0; k < b.dims[2]; ++k)
    for (std::int64_t j = 0; j < b.dims[1]; ++j)
      for (std::int64_t i = 0; i < b.dims[0]; ++i) f(i, j, k);
}

}  // namespace

namespace {

std::vector<Vec3> image_points(const VtkXmlDocument& doc, const pugi::xml_node& dataset,
                               const Block& b) {
  const auto origin = numbers<3>(doc, dataset, "Origin", {0, 0, 0});
  const auto spacing = numbers<3>(doc, dataset, "Spacing", {1, 1, 1});
  const auto dir = numbers<9>(doc, dataset, "Direction", {1, 0, 0, 0, 1, 0, 0, 0, 1});
  Eigen::Matrix3d direction;
  direction << dir[0], dir[1], dir[2], dir[3], dir[4], dir[5], dir[6], dir[7], dir[8];
  const bool identity = direction == Eigen::Matrix3d::Identity();
  const Vec3 o(origin[0], origin[1], origin[2]);
  std::vector<Vec3> points;
  points.reserve(b.n_points);
  for_each_point(b, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    // Index (i, j, k) of the extent, scaled by the spacing, rotated by the direction.
    const Vec3 local(static_cast<double>(b.extent[0] + i) * spacing[0],
                     static_cast<double>(b.extent[2] + j) * spacing[1],
                     static_cast<double>(b.extent[4] + k) * spacing[2]);
    points.push_back(identity ? Vec3(o + local) : Vec3(o + direction * local));
  });
  return points;
}

std::vector<Vec3> rectilinear_points(const VtkXmlDocument& doc, const pugi::xml_node& piece,
                                     const Block& b) {
  const pugi::xml_node coords = piece.child("Coordinates");
  if (!coords) throw InputError(doc.file, place(piece), "no <Coordinates> element");
  std::array<std::vector<double>, 3> axis;
  pugi::xml_node e = coords.child("DataArray");
  for (std::size_t a = 0; a < 3; ++a, e = e.next_sibling("DataArray")) {
    if (!e) throw InputError(doc.file, place(coords), "expected 3 coordinate arrays (x, y, z)");
    axis[a] = read_data_array(doc, e, static_cast<std::size_t>(b.dims[a]), 1).values;
  }
  std::vector<Vec3> points;
  points.reserve(b.n_points);
  for_each_point(b, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    points.emplace_back(axis[0][static_cast<std::size_t>(i)], axis[1][static_cast<std::size_t>(j)],
                        axis[2][static_cast<std::size_t>(k)]);
  });
  return points;
}

std::vector<Vec3> grid_points(const VtkXmlDocument& doc, const pugi::xml_node& piece,
                              const Block& b) {
  const pugi::xml_node pts = piece.child("Points");
  if (!pts || !pts.child("DataArray"))
    throw InputError(doc.file, place(piece), "no <Points> element with a DataArray");
  const DataArray a = read_data_array(doc, pts.child("DataArray"), b.n_points, 3);
  std::vector<Vec3> points(b.n_points);
  for (std::size_t k = 0; k < b.n_points; ++k)
    points[k] = Vec3(a.values[3 * k], a.values[3 * k + 1], a.values[3 * k + 2]);
  return points;
}

}  // namespace

StructuredPiece read_structured_piece(const VtkXmlDocument& doc) {
  const pugi::xml_node dataset = doc.root.child(doc.type.c_str());
  const pugi::xml_node piece = single_piece(doc, dataset);
  const Block b = block_of(doc, dataset, piece);
  StructuredPiece out;
  out.extent = b.extent;
  out.dims = b.dims;
  // Arrays first: their sizes are checked against the file before points are allocated.
  read_attributes(doc, dataset, piece, b.n_points, b.n_cells, out.data);
  if (doc.type == "ImageData") {
    refuse_empty_lattice(doc, piece, b, out.data);
    out.data.points = image_points(doc, dataset, b);
  } else if (doc.type == "RectilinearGrid") {
    refuse_empty_lattice(doc, piece, b, out.data);
    out.data.points = rectilinear_points(doc, piece, b);
  } else {
    out.data.points = grid_points(doc, piece, b);
  }
  return out;
}

void read_structured(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data) {
  StructuredPiece p = read_structured_piece(doc);
  data = std::move(p.data);
  std::vector<Vec3> points = std::move(data.points);
  fill_structured(data, p.dims, std::move(points), options, doc.file);
}

}  // namespace hexadapt::io::detail
