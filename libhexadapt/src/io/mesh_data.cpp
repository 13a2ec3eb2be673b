#include "hexadapt/io/mesh_data.h"

#include <algorithm>

#include "hexadapt/core/error.h"

namespace hexadapt::io {

namespace {

template <class Array>
const DataArray* find(const Array& arrays, const std::string& name) {
  for (const auto& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

void set(std::vector<DataArray>& arrays, DataArray a, std::size_t n_tuples, const char* kind) {
  if (a.n_components < 1 || a.values.size() != n_tuples * static_cast<std::size_t>(a.n_components))
    throw Error(std::string(kind) + " array " + quote_token(a.name) + " has " +
                std::to_string(a.values.size()) + " values, expected " + std::to_string(n_tuples) +
                " x " + std::to_string(a.n_components));
  for (auto& old : arrays)
    if (old.name == a.name) {
      old = std::move(a);
      return;
    }
  arrays.push_back(std::move(a));
}

template <std::size_t N>
std::vector<std::array<NodeId, N>> group(const std::vector<NodeId>& flat) {
  std::vector<std::array<NodeId, N>> cells(flat.size() / N);
  for (std::size_t c = 0; c < cells.size(); ++c)
    std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(c * N), N, cells[c].begin());
  return cells;
}

template <class M>
MeshData from_kernel(const M& mesh) {
  MeshData d;
  d.dim = M::dim;
  d.points.reserve(static_cast<std::size_t>(mesh.n_nodes()));
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) d.points.push_back(mesh.point(n));
  d.cells.reserve(static_cast<std::size_t>(mesh.n_cells()) * M::nodes_per_cell);
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const auto v = mesh.cell_nodes(c);
    d.cells.insert(d.cells.end(), v.begin(), v.end());
  }
  return d;
}

}  // namespace

void MeshData::check_array_sizes(const std::string& path) const {
  for (const auto* group : {&point_data, &cell_data})
    for (const DataArray& a : *group)
      if (a.n_components < 1 ||
          a.values.size() !=
              static_cast<std::size_t>(a.n_components) *
                  (group == &point_data ? points.size() : static_cast<std::size_t>(n_cells())))
        throw OptionError(path + ": array '" + a.name + "' does not match the mesh size");
}

const DataArray* MeshData::find_cell_array(const std::string& name) const {
  return find(cell_data, name);
}
const DataArray* MeshData::find_point_array(const std::string& name) const {
  return find(point_data, name);
}
void MeshData::set_cell_array(DataArray a) {
  set(cell_data, std::move(a), static_cast<std::size_t>(n_cells()), "cell");
}
void MeshData::set_point_array(DataArray a) {
  set(point_data, std::move(a), points.size(), "point");
}

AnyMesh to_mesh(const MeshData& data) {
  if (data.dim == 2) return QuadMesh(data.points, group<4>(data.cells));
  if (data.dim == 3) return HexMesh(data.points, group<8>(data.cells));
  throw InputError("", "", "the data set has no quad or hex cells");
}

AnyMesh to_mesh(const MeshData& data, const std::string& file) {
  try {
    return to_mesh(data);
  } catch (const MeshError& e) {
    throw MeshError(file + ": " + e.what());
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(file, e.where(), e.message());
  }
}

MeshData from_mesh(const QuadMesh& mesh) {
  return from_kernel(mesh);
}
MeshData from_mesh(const HexMesh& mesh) {
  return from_kernel(mesh);
}
MeshData from_mesh(const AnyMesh& mesh) {
  return std::visit([](const auto& m) { return from_kernel(m); }, mesh);
}

}  // namespace hexadapt::io
