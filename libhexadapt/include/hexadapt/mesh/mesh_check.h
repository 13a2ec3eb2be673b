// The mesh check: is a quad / hex mesh a valid conformal, manifold, untangled mesh?
//
// The pipeline's output must be conformal and every cell valid (paper sec. 1 and 5); this is
// the independent check that tests and hexadapt-measure run on any mesh. One source for 2D
// and 3D (DESIGN sec. 3): check_mesh is written once against the cell-complex interface
// (cell_complex.h) and instantiated for QuadMesh and HexMesh. It finds
//   - hanging nodes (T-junctions): a node lying on a boundary face (2D: edge) of a cell
//     without being one of its corners, inside the face or on one of its edges. In a
//     conformal mesh only the domain boundary has boundary faces, so such a node betrays two
//     cells that touch without sharing their nodes. Candidates come from a uniform grid
//     over the boundary nodes, so the cost is linear in the boundary size;
//   - unreferenced nodes (used by no cell);
//   - duplicate nodes: distinct ids closer than a tolerance relative to the bounding box
//     (uniform grid with the tolerance as bucket size);
//   - inverted cells: scaled Jacobian <= 0 (degenerate cells score -1, so they count too);
//   - non-manifold nodes: the cells around a node are not connected through faces holding
//     the node (bow-ties: cells touching at a node or, in 3D, along an edge only), or the
//     boundary faces around the node do not form one fan (2D: exactly 0 or 2 boundary edges;
//     3D: the boundary faces at the node close into one cycle around it, or there are none).
//     This covers the pinched configurations the kernels can represent; faces shared by more
//     than two cells cannot be represented at all (the kernels throw MeshError).
#pragma once

#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/mesh/part_ids.h"

namespace hexadapt {

struct MeshCheckOptions {
  /// Nodes closer than this times the bounding-box diagonal are duplicates.
  double duplicate_tolerance = 1e-10;
  /// A node within this times the face's diameter of a boundary face lies on it.
  double conformity_tolerance = 1e-6;
  /// How many offenders of each kind are listed (all of them are counted).
  int max_listed = 10;
};

/// One offending node (for hanging nodes: the cell and local face it lies on).
struct NodeIssue {
  NodeId node;
  Vec3 position = Vec3::Zero();
  CellId cell;  ///< hanging: the cell whose boundary face holds the node
  int local_face = -1;
  NodeId other;  ///< duplicates: the lower-id node at the same place
};

struct CellIssue {
  CellId cell;
  double quality = 0;  ///< the cell's scaled Jacobian
  Vec3 centroid = Vec3::Zero();
};

struct MeshCheckResult {
  index_t hanging_nodes = 0;       ///< distinct nodes lying on another cell's boundary face
  index_t nonconformal_faces = 0;  ///< boundary faces holding at least one hanging node
  index_t unreferenced_nodes = 0;
  index_t duplicate_nodes = 0;  ///< nodes with a lower-id node within the tolerance
  index_t inverted_cells = 0;   ///< scaled Jacobian <= 0
  index_t nonmanifold_nodes = 0;
  index_t boundary_faces = 0;     ///< faces (2D: edges) with a cell on one side only
  double duplicate_distance = 0;  ///< the absolute tolerance used for duplicates
  std::vector<NodeIssue> first_hanging, first_unreferenced, first_duplicates, first_nonmanifold;
  std::vector<CellIssue> first_inverted;

  bool ok() const {
    return hanging_nodes == 0 && unreferenced_nodes == 0 && duplicate_nodes == 0 &&
           inverted_cells == 0 && nonmanifold_nodes == 0;
  }
};

/// Every rank's listed issues (each list in increasing id) merged by id and cut to the
/// first k: the same on every rank. Every rank calls them.
std::vector<NodeIssue> first_of_ranks(const dist::Communicator& comm, std::vector<NodeIssue> mine,
                                      int k);
std::vector<CellIssue> first_of_ranks(const dist::Communicator& comm, std::vector<CellIssue> mine,
                                      int k);

/// Checks a QuadMesh or HexMesh (instantiated for both). Deterministic: offenders are listed
/// by increasing id whatever the thread count.
template <class M>
MeshCheckResult check_mesh(const M& mesh, const MeshCheckOptions& options = {});

/// The same check of a mesh spread over ranks, each holding a part (`part`, numbered by
/// `ids`) with a ghost layer of every cell sharing a node with one of its owned cells
/// (io::with_ghost_layers): the result of the whole mesh, ids global, the same on every rank
/// and equal to check_mesh of the whole mesh. Every rank calls it.
template <class M>
MeshCheckResult check_mesh(const dist::Communicator& comm, const M& part, const PartIds& ids,
                           const MeshCheckOptions& options = {});

}  // namespace hexadapt
