// Node-to-target distances (see target_distance.h).
#include "hexadapt/measure/target_distance.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "hexadapt/core/error.h"
#include "hexadapt/core/exact_sum.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_part.h"
#include "rank_figures.h"

namespace hexadapt {

namespace {

// The distances of the nodes every rank owns (`mesh` a rank's part numbered by `ids`).
TargetDistances distances_of(const dist::Communicator& comm, const io::MeshData& mesh,
                             const PartIds& ids, const std::string& array) {
  TargetDistances r;
  const io::DataArray* a = mesh.find_point_array(array);
  if (!a) return r;
  if (a->n_components != 3)
    throw InputError({}, "point array '" + array + "'",
                     "expected 3 components, found " + std::to_string(a->n_components));
  r.has_targets = true;
  ExactSum sum;
  std::int64_t nodes = 0, max_node = -1;
  for (NodeId n : id_range<NodeId>(mesh.n_points())) {
    if (!ids.owns_node(n.idx())) continue;
    const Vec3 t(a->values[3 * n.idx()], a->values[3 * n.idx() + 1], a->values[3 * n.idx() + 2]);
    if (!t.allFinite()) continue;
    const double d = (mesh.points[n.idx()] - t).stableNorm();  // no underflow at 1e-300
    ++nodes;
    sum.add(d);
    if (nodes == 1 || d > r.max) {
      r.max = d;
      max_node = ids.node(n.idx());
    }
  }
  r.nodes = static_cast<index_t>(total(comm, nodes));
  r.sum = dist::exact_sum(comm, sum);
  const auto [max, node] = extreme_with_id(comm, {r.max, max_node}, /*highest=*/true);
  r.max = max;
  r.max_node = NodeId(node);
  return r;
}

}  // namespace

TargetDistances target_distances(const io::MeshData& mesh, const std::string& array) {
  return distances_of(dist::serial(), mesh, PartIds(), array);
}

TargetDistances target_distances(const dist::Communicator& comm, const io::GhostedPart& part,
                                 const std::string& array) {
  return distances_of(comm, part.part.data, io::part_ids(part), array);
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
