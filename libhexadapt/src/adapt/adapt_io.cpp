#include "hexadapt/adapt/adapt_io.h"

#include <string>

#include "hexadapt/io/material_names.h"

namespace hexadapt {

template <class M>
io::MeshData adapt_mesh_data(const AdaptResult<M>& result,
                             const std::vector<std::string>& material_names) {
  io::MeshData data = io::from_mesh(result.mesh);
  io::DataArray material{"material", 1, io::ScalarType::int32, {}};
  for (int m : result.material) material.values.push_back(m);
  data.set_cell_array(std::move(material));
  io::DataArray local_size{"local_size", 1, io::ScalarType::float64, result.local_size.raw()};
  data.set_cell_array(std::move(local_size));
  io::DataArray target{"target", 3, io::ScalarType::float64, {}};
  io::DataArray distance{"distance", 1, io::ScalarType::float64, {}};
  for (NodeId v : id_range<NodeId>(result.mesh.n_nodes())) {
    for (int k = 0; k < 3; ++k) target.values.push_back(result.target[v][k]);
    distance.values.push_back(result.distance[v]);
  }
  data.set_point_array(std::move(target));
  data.set_point_array(std::move(distance));
  data.set_point_array(
      {"surface_distance", 1, io::ScalarType::float64, result.surface_distance.raw()});
  // Why a node is short of its target (BlockReason: 0 none, 1 quality of the cells around,
  // 2 and no cavity, 3 frozen).
  io::DataArray blocked{"blocked", 1, io::ScalarType::int32, {}};
  for (NodeId v : id_range<NodeId>(result.mesh.n_nodes()))
    blocked.values.push_back(result.blocked.empty() ? 0 : result.blocked[v]);
  data.set_point_array(std::move(blocked));
  io::set_material_names(data, material_names);
  return data;
}

template io::MeshData adapt_mesh_data<QuadMesh>(const AdaptResult<QuadMesh>&,
                                                const std::vector<std::string>&);
template io::MeshData adapt_mesh_data<HexMesh>(const AdaptResult<HexMesh>&,
                                               const std::vector<std::string>&);

}  // namespace hexadapt
