// Node-to-target distances (see target_distance.h).
#include "hexadapt/measure/target_distance.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt {

TargetDistances target_distances(const io::MeshData& mesh, const std::string& array) {
  TargetDistances r;
  const io::DataArray* a = mesh.find_point_array(array);
  if (!a) return r;
  if (a->n_components != 3)
    throw InputError({}, "point array '" + array + "'",
                     "expected 3 components, found " + std::to_string(a->n_components));
  r.has_targets = true;
  for (NodeId n : id_range<NodeId>(mesh.n_points())) {
    const Vec3 t(a->values[3 * n.idx()], a->values[3 * n.idx() + 1], a->values[3 * n.idx() + 2]);
    if (!t.allFinite()) continue;
    const double d = (mesh.points[n.idx()] - t).stableNorm();  // no underflow at 1e-300
    ++r.nodes;
    r.sum += d;
    if (r.nodes == 1 || d > r.max) {
      r.max = d;
      r.max_node = n;
    }
  }
  return r;
}

std::string target_distances_json(const TargetDistances& d) {
  nlohmann::ordered_json j;
  j["target_array"] = d.has_targets;
  j["nodes"] = d.nodes;
  j["dist"] = d.sum;
  j["max"] = d.max;
  j["max_node"] = d.max_node.valid() ? nlohmann::ordered_json(d.max_node.value())
                                     : nlohmann::ordered_json(nullptr);
  return j.dump();
}

}  // namespace hexadapt
