// Cells as convex pieces for the imprint (imprint.h).
//
// A hex's faces need not be planar, so the region a hex stands for is fixed here once, the
// same way on both sides of every face: each face is split into two triangles along the
// diagonal through its node of lowest global id, and the hex is the union of the 12
// tetrahedra joining its centroid to those triangles. Neighbours therefore agree on their
// shared faces and the cells of a conformal mesh tile their union exactly. A quad is its
// polygon.
//
// An input cell (the clipping side) is described by convex pieces, each an intersection of
// half-spaces: a convex cell is one piece (its face planes, or triangle planes on a folded
// face). A hex whose folded faces make valleys is its hull H (those faces split along their
// other diagonal, which makes ridges) minus one thin tetrahedron per valley face (the four
// corners of the face), when H is convex and the notches are thin; otherwise, and for a
// non-convex quad, each tetrahedron (triangle) is a piece. Since folds are the rule on
// jittered grids, this keeps most cells at one piece plus a few notches instead of 12.
#pragma once

#include <array>
#include <vector>

#include "clip.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::clip {

struct Tet {
  std::array<Vec3, 4> p;  ///< positively oriented corners
  double sign = 1;        ///< -1 when the cell was inverted here (the corners were swapped)
};

/// A convex piece: the intersection of the half-spaces, a box around it, and whether it
/// adds to the cell or is taken out of it (a notch).
struct Piece {
  std::vector<Plane> planes;
  Eigen::AlignedBox3d box;
  double sign = 1;  ///< +1, or -1 for a notch
};

/// The 12 tetrahedra of hex `cell` of the data (3D).
std::array<Tet, 12> hex_tets(const io::MeshData& data, index_t cell);
/// The quad's polygon (2D), counter-clockwise; sign -1 when the quad was clockwise.
Polygon quad_polygon(const io::MeshData& data, index_t cell, double* sign);

/// Convex pieces of input cell `cell`; `tolerance` (relative to the cell's diagonal) decides
/// when a face is planar and a cell convex. Also returns the cell's volume (area).
std::vector<Piece> convex_pieces(const io::MeshData& data, index_t cell, double tolerance,
                                 double* volume);

}  // namespace hexadapt::clip
