#include "hexadapt/adapt/warm_start.h"

#include <algorithm>
#include <unordered_map>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt {

namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  // splitmix64's finaliser on the running hash and the next value
  std::uint64_t z = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Where each name occurs once: its index; names occurring more than once are dropped.
std::unordered_map<std::uint64_t, std::size_t> unique_names(const std::vector<std::uint64_t>& n) {
  std::unordered_map<std::uint64_t, std::size_t> at;
  std::vector<std::uint64_t> twice;
  at.reserve(n.size());
  for (std::size_t i = 0; i < n.size(); ++i)
    if (!at.emplace(n[i], i).second) twice.push_back(n[i]);
  for (std::uint64_t t : twice) at.erase(t);
  return at;
}

}  // namespace

template <class M>
NodePlaces node_places(const M& mesh, const IdVector<NodeId, NodeId>& node_origin,
                       const IdVector<CellId, CellId>& cell_origin) {
  if (node_origin.size() != static_cast<std::size_t>(mesh.n_nodes()) ||
      cell_origin.size() != static_cast<std::size_t>(mesh.n_cells()))
    throw InternalError("node places: origins do not match the mesh");
  NodePlaces out;
  std::vector<index_t> origins;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    origins.clear();
    for (CellId c : mesh.node_cells(v)) origins.push_back(cell_origin[c].value());
    std::sort(origins.begin(), origins.end());
    std::uint64_t h = mix(0, static_cast<std::uint64_t>(node_origin[v].value()));
    for (index_t o : origins) h = mix(h, static_cast<std::uint64_t>(o));
    out.name.push_back(h);
    out.point.push_back(mesh.point(v));
  }
  return out;
}

template <class M>
std::vector<NodeId> warm_start(M& mesh, const NodePlaces& now, const NodePlaces& before) {
  if (now.name.size() != static_cast<std::size_t>(mesh.n_nodes()))
    throw InternalError("warm start: the places do not match the mesh");
  const auto here = unique_names(now.name);
  const auto there = unique_names(before.name);
  // Each node's index in `before`, or -1 when its name is not once in both.
  std::vector<std::int64_t> match(now.name.size(), -1);
  for (std::size_t i = 0; i < now.name.size(); ++i) {
    const auto t = there.find(now.name[i]);
    if (t != there.end() && here.count(now.name[i]))
      match[i] = static_cast<std::int64_t>(t->second);
  }
  // Warm: matched, and so is every node of its cells (a node of no cell only needs a match).
  std::vector<char> warm(now.name.size(), 0);
  for (std::size_t i = 0; i < match.size(); ++i) warm[i] = match[i] >= 0;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes()))
    if (match[v.idx()] < 0)
      for (CellId c : mesh.node_cells(v))
        for (NodeId o : mesh.cell_nodes(c)) warm[o.idx()] = 0;
  std::vector<NodeId> start;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    if (warm[v.idx()]) {
      mesh.set_point(v, before.point[static_cast<std::size_t>(match[v.idx()])]);
      continue;
    }
    for (CellId c : mesh.node_cells(v))
      for (NodeId o : mesh.cell_nodes(c)) start.push_back(o);
  }
  std::sort(start.begin(), start.end());
  start.erase(std::unique(start.begin(), start.end()), start.end());
  return start;
}

template NodePlaces node_places<QuadMesh>(const QuadMesh&, const IdVector<NodeId, NodeId>&,
                                          const IdVector<CellId, CellId>&);
template NodePlaces node_places<HexMesh>(const HexMesh&, const IdVector<NodeId, NodeId>&,
                                         const IdVector<CellId, CellId>&);
template std::vector<NodeId> warm_start<QuadMesh>(QuadMesh&, const NodePlaces&, const NodePlaces&);
template std::vector<NodeId> warm_start<HexMesh>(HexMesh&, const NodePlaces&, const NodePlaces&);

}  // namespace hexadapt
