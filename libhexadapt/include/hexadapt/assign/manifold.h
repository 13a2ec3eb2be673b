// The manifold test of the paper's sec. 3.2, eq. (3): is material m a manifold at node n?
//
// Take the cells of n's ball assigned to m and their union U. Its boundary is made of the
// faces used once (a face shared by two cells of U is inside it). Counting the vertices V,
// edges E and faces F of that boundary, U is a ball only if V - E + F = 2 (3D); in 2D the
// boundary is a set of edges and U is a disk only if V - E = 0. A single cell always passes.
//
// The Euler count alone is not enough. It reads the boundary as a whole, and a pinch can be
// offset elsewhere: six cells of a 2x2x2 block whose two missing cells share an edge through
// the centre are face-connected with V - E + F = 2, yet two of them meet only along that
// edge (36 of the 256 labellings of that block fool the count; see the tests). So a material
// is manifold at n when, in addition to the Euler count,
//   - its cells are connected through shared faces, and
//   - (3D) around every edge through n its cells form a single run.
// With these conditions the test agrees with the link criterion (the corners of m's cells
// at n form one disk, or the whole sphere/circle) on every labelling of every structured
// ball, interior or on the domain boundary; the tests check it exhaustively with an
// independent implementation of that criterion.
//
// Nodes on the domain boundary (the cut ball): the test is the same. Faces on the domain
// boundary are faces used once, so they are boundary faces of U like any interface face, and
// U must be a manifold solid in space. The domain boundary is not a material: a material may
// touch it along any shape (even at the single node n), while two cells of a material that
// meet only at n or along an edge through n are rejected whether n is inside or on the
// boundary. In a structured grid this leaves boundary nodes of 2D grids and edge and corner
// nodes of 3D grids always manifold; a node on a face of a 3D grid (4 cells) is non-manifold
// exactly when its material forms a diagonal pair.
#pragma once

#include <vector>

#include "hexadapt/assign/local_ball.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::assign {

/// V - E + F (3D) or V - E (2D) of the boundary of the union of the ball's cells labelled m.
/// `labels` holds one material per ball cell, in ball order.
template <class M>
int euler_characteristic(const LocalBall<M>& ball, const std::vector<int>& labels, int m);

/// Manifold test of material m over the ball (Euler count, face connectivity, edge runs).
template <class M>
bool is_manifold(const LocalBall<M>& ball, const std::vector<int>& labels, int m);

/// True when every material present in `labels` is manifold over the ball.
template <class M>
bool is_manifold(const LocalBall<M>& ball, const std::vector<int>& labels);

/// The materials present around node n that are not manifold there, increasing.
template <class M>
std::vector<int> non_manifold_materials(const M& mesh, const CellMaterials& labels, NodeId n);

/// Every node where some material is not manifold, increasing ids (parallel scan).
template <class M>
std::vector<NodeId> non_manifold_nodes(const M& mesh, const CellMaterials& labels);

/// The subset of `nodes` (any order) that are non-manifold, increasing ids (parallel).
template <class M>
std::vector<NodeId> non_manifold_among(const M& mesh, const CellMaterials& labels,
                                       std::vector<NodeId> nodes);

}  // namespace hexadapt::assign
