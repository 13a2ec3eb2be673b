// The steps of check_mesh (mesh_check.h), one file each, templates over the cell complex
// explicitly instantiated for QuadMesh and HexMesh. Each runs on a rank's part of the mesh
// (the whole mesh on one rank): it counts and lists what the rank owns, by global id; the
// counts and lists of the ranks are combined afterwards (check_mesh).
#pragma once

#include <vector>

#include "hexadapt/dist/communicator.h"
#include "hexadapt/mesh/mesh_check.h"
#include "hexadapt/mesh/part_ids.h"

namespace hexadapt::mesh_check_detail {

/// A local face of a cell.
struct FaceRef {
  CellId cell;
  int local_face = -1;
};

/// Every point of the mesh, indexed by node id.
template <class M>
std::vector<Vec3> all_points(const M& mesh);

/// Faces of the owned cells with a cell on one side only, in increasing (cell, local face).
/// With a ghost layer around the owned cells, these are exactly the mesh's boundary faces
/// of those cells.
template <class M>
std::vector<FaceRef> boundary_faces(const M& mesh, const PartIds& ids);

/// Every rank calls it. Other ranks' nodes are appended to `points` while it runs; it
/// leaves `points` as it found them.
template <class M>
void find_hanging_nodes(const dist::Communicator& comm, const M& mesh, const PartIds& ids,
                        std::vector<Vec3>& points, const std::vector<FaceRef>& boundary,
                        const MeshCheckOptions& options, MeshCheckResult& result);

/// Every rank calls it; `points` as find_hanging_nodes.
void find_duplicate_nodes(const dist::Communicator& comm, const PartIds& ids,
                          std::vector<Vec3>& points, const MeshCheckOptions& options,
                          MeshCheckResult& result);

template <class M>
void find_nonmanifold_nodes(const M& mesh, const PartIds& ids, const std::vector<Vec3>& points,
                            const MeshCheckOptions& options, MeshCheckResult& result);

/// Distance from p to the face given by its corners in cyclic order (a segment in 2D, a
/// bilinear patch in 3D), and whether the closest point is a corner.
double distance_to_segment(const Vec3& a, const Vec3& b, const Vec3& p);
double distance_to_bilinear(const std::array<Vec3, 4>& q, const Vec3& p);

}  // namespace hexadapt::mesh_check_detail
