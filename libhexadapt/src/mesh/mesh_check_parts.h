// The steps of check_mesh (mesh_check.h), one file each, templates over the cell complex
// explicitly instantiated for QuadMesh and HexMesh.
#pragma once

#include <vector>

#include "hexadapt/mesh/mesh_check.h"

namespace hexadapt::mesh_check_detail {

/// A local face of a cell.
struct FaceRef {
  CellId cell;
  int local_face = -1;
};

/// Every point of the mesh, indexed by node id.
template <class M>
std::vector<Vec3> all_points(const M& mesh);

/// Faces with a cell on one side only, in increasing (cell, local face).
template <class M>
std::vector<FaceRef> boundary_faces(const M& mesh);

template <class M>
void find_hanging_nodes(const M& mesh, const std::vector<Vec3>& points,
                        const std::vector<FaceRef>& boundary, const MeshCheckOptions& options,
                        MeshCheckResult& result);

void find_duplicate_nodes(const std::vector<Vec3>& points, const MeshCheckOptions& options,
                          MeshCheckResult& result);

template <class M>
void find_nonmanifold_nodes(const M& mesh, const std::vector<Vec3>& points,
                            const MeshCheckOptions& options, MeshCheckResult& result);

/// Distance from p to the face given by its corners in cyclic order (a segment in 2D, a
/// bilinear patch in 3D), and whether the closest point is a corner.
double distance_to_segment(const Vec3& a, const Vec3& b, const Vec3& p);
double distance_to_bilinear(const std::array<Vec3, 4>& q, const Vec3& p);

}  // namespace hexadapt::mesh_check_detail
