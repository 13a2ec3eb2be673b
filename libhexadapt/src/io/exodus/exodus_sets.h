// Private to the Exodus II writer: the side sets and node sets of a mesh with one material
// per cell (naming in hexadapt/io/exodus.h). Faces are matched by their sorted node ids, so
// any conformal quad or hex mesh works, structured or not.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io::detail {

struct SideSet {
  std::string name;
  std::vector<int> elements;  ///< element numbers in the file (1-based)
  std::vector<int> sides;     ///< Exodus side numbers (1-based), one per element
};

struct NodeSet {
  std::string name;
  std::vector<int> nodes;  ///< node numbers (1-based), increasing
};

struct MeshSets {
  std::vector<SideSet> side_sets;
  std::vector<NodeSet> node_sets;
};

/// The sets `which` asks for. `material[c]` is cell c's material index into `names`,
/// `element_of_cell[c]` its element number in the file. Domain sides come first (all of
/// them, empty or not), then the material pairs that touch, in the order of the pairs.
MeshSets mesh_sets(const MeshData& data, const std::vector<int>& material,
                   const std::vector<std::string>& names, const std::vector<int>& element_of_cell,
                   ExodusSets which);

/// The Exodus side number (1-based) of a kernel-order local face: quads' edge k is side
/// k + 1; hexes' faces x-, x+, y-, y+, z-, z+ are HEX8 sides 4, 2, 1, 3, 5, 6.
int exodus_side(int dim, int local_face);

}  // namespace hexadapt::io::detail
