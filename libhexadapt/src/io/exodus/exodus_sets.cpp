#include "exodus_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "hexadapt/core/geometry.h"

namespace hexadapt::io::detail {

namespace {

constexpr std::array<int, 6> hex_side = {4, 2, 1, 3, 5, 6};
constexpr std::array<const char*, 6> side_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

struct FaceRef {
  std::array<index_t, 4> key;  // sorted node ids (quads: two, then -1)
  index_t cell;
  int local_face;
  bool operator<(const FaceRef& o) const {
    return key != o.key ? key < o.key : cell != o.cell ? cell < o.cell : local_face < o.local_face;
  }
};

int n_faces(int dim) {
  return dim == 3 ? ref_hex::n_faces : ref_quad::n_faces;
}

std::vector<index_t> face_nodes(const MeshData& d, index_t cell, int lf) {
  const std::size_t base =
      static_cast<std::size_t>(cell) * static_cast<std::size_t>(d.nodes_per_cell());
  std::vector<index_t> out;
  if (d.dim == 3) {
    for (int k : ref_hex::face_nodes[static_cast<std::size_t>(lf)])
      out.push_back(d.cells[base + static_cast<std::size_t>(k)].value());
  } else {
    for (int k : ref_quad::face_nodes[static_cast<std::size_t>(lf)])
      out.push_back(d.cells[base + static_cast<std::size_t>(k)].value());
  }
  return out;
}

// Every face of every cell, sorted so that the two sides of an inner face are neighbours.
std::vector<FaceRef> sorted_faces(const MeshData& d) {
  std::vector<FaceRef> faces;
  faces.reserve(static_cast<std::size_t>(d.n_cells()) * static_cast<std::size_t>(n_faces(d.dim)));
  for (index_t c = 0; c < d.n_cells(); ++c)
    for (int lf = 0; lf < n_faces(d.dim); ++lf) {
      FaceRef f{{-1, -1, -1, -1}, c, lf};
      std::vector<index_t> nodes = face_nodes(d, c, lf);
      std::sort(nodes.begin(), nodes.end());
      std::copy(nodes.begin(), nodes.end(), f.key.begin());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  return faces;
}

Vec3 centre(const MeshData& d, const std::vector<index_t>& nodes) {
  Vec3 s(0, 0, 0);
  for (index_t n : nodes) s += d.points[static_cast<std::size_t>(n)];
  return s / static_cast<double>(nodes.size());
}

// xmin .. zmax: the dominant direction from the cell's centre to the face's centre.
int domain_side(const MeshData& d, const FaceRef& f) {
  std::vector<index_t> cell_nodes;
  const std::size_t npc = static_cast<std::size_t>(d.nodes_per_cell());
  for (std::size_t k = 0; k < npc; ++k)
    cell_nodes.push_back(d.cells[static_cast<std::size_t>(f.cell) * npc + k].value());
  const Vec3 v = centre(d, face_nodes(d, f.cell, f.local_face)) - centre(d, cell_nodes);
  int axis = 0;
  for (int a = 1; a < d.dim; ++a)
    if (std::abs(v[a]) > std::abs(v[axis])) axis = a;
  return 2 * axis + (v[axis] > 0 ? 1 : 0);
}

void add_nodes(std::vector<int>& set, const std::vector<index_t>& nodes) {
  for (index_t n : nodes) set.push_back(static_cast<int>(n) + 1);
}

void finish_node_set(NodeSet& s) {
  std::sort(s.nodes.begin(), s.nodes.end());
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
}

}  // namespace

int exodus_side(int dim, int local_face) {
  return dim == 3 ? hex_side[static_cast<std::size_t>(local_face)] : local_face + 1;
}

MeshSets mesh_sets(const MeshData& data, const std::vector<int>& material,
                   const std::vector<std::string>& names, const std::vector<int>& element_of_cell,
                   ExodusSets which) {
  const bool boundary = which == ExodusSets::boundary || which == ExodusSets::all;
  const bool interfaces = which == ExodusSets::interfaces || which == ExodusSets::all;
  MeshSets out;
  if (!boundary && !interfaces) return out;
  std::vector<SideSet> sides(static_cast<std::size_t>(2 * data.dim));
  std::vector<NodeSet> side_nodes(sides.size());
  for (std::size_t s = 0; s < sides.size(); ++s) sides[s].name = side_nodes[s].name = side_names[s];
  // Interfaces by (material of the cell, material across): ordered pairs.
  std::map<std::pair<int, int>, SideSet> pair_sides;
  std::map<std::pair<int, int>, NodeSet> pair_nodes;
  const auto add_side = [&](SideSet& s, const FaceRef& f) {
    s.elements.push_back(element_of_cell[static_cast<std::size_t>(f.cell)]);
    s.sides.push_back(exodus_side(data.dim, f.local_face));
  };
  const std::vector<FaceRef> faces = sorted_faces(data);
  for (std::size_t i = 0; i < faces.size();) {
    const bool paired = i + 1 < faces.size() && faces[i + 1].key == faces[i].key;
    const FaceRef& f = faces[i];
    if (!paired) {
      if (boundary) {
        const auto s = static_cast<std::size_t>(domain_side(data, f));
        add_side(sides[s], f);
        add_nodes(side_nodes[s].nodes, face_nodes(data, f.cell, f.local_face));
      }
      ++i;
      continue;
    }
    const FaceRef& g = faces[i + 1];
    const int a = material[static_cast<std::size_t>(f.cell)];
    const int b = material[static_cast<std::size_t>(g.cell)];
    if (interfaces && a != b) {
      add_side(pair_sides[{a, b}], f);
      add_side(pair_sides[{b, a}], g);
      add_nodes(pair_nodes[{std::min(a, b), std::max(a, b)}].nodes,
                face_nodes(data, f.cell, f.local_face));
    }
    i += 2;
  }
  if (boundary) {
    out.side_sets = std::move(sides);
    out.node_sets = std::move(side_nodes);
  }
  const auto name = [&](int m) { return names[static_cast<std::size_t>(m)]; };
  for (auto& [pair, s] : pair_sides) {
    s.name = name(pair.first) + "_" + name(pair.second);
    out.side_sets.push_back(std::move(s));
  }
  for (auto& [pair, s] : pair_nodes) {
    s.name = name(pair.first) + "_" + name(pair.second);
    out.node_sets.push_back(std::move(s));
  }
  for (NodeSet& s : out.node_sets) finish_node_set(s);
  return out;
}

}  // namespace hexadapt::io::detail
