// Pillowing a set of cells (paper sec. 5, footnote 1; Mitchell and Tautges 1995): a layer of
// cells is inserted between the set and the rest of the mesh, each layer cell inflated from
// one face of the set's boundary.
//
// The nodes on the pillowed faces are duplicated: the cells of the set take the copies, the
// other cells keep the originals, and each pillowed face becomes a new cell joining the two.
// Where the set touches itself only along an edge or at a node (a non-manifold region) each
// face-connected fan of the set's cells around a node gets its own copy, so the result stays
// conformal. That fails where two cells touching along an edge only are also joined through
// other set cells around both ends of the edge: both must then take the same copies of the
// edge's nodes, so the four layer cells at the edge would share one face, which no layer of
// cells avoids; the kernel throws MeshError. Faces on the domain boundary are not pillowed.
// A new node starts a fraction of the way from its original toward the centre of the fan's
// cells (kept on the domain boundary when the original is on it); smoothing is the caller's
// next step. With a size criterion (size_criterion.h) a copy starts far enough from its
// original for the layer's edges across to meet it. Used for the global pillowing of the base algorithm (each material in turn)
// and, in the guaranteed pipeline, for cavities (sec. 5.2). The mesh is rebuilt, never
// edited in place.
#pragma once

#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"

namespace hexadapt {

struct PillowOptions {
  /// Where a duplicated node starts: this fraction of the way toward its fan's cell centre.
  double offset = 0.25;
  /// With a size criterion: a copy starts at least this many times the shortest edge its
  /// fan's cells may have from its original (the layer's thickness)...
  double min_thickness = 1.5;
  /// ... but never farther than this fraction of the way toward the fan's cell centre.
  double max_offset = 0.5;
};

/// The pillowed mesh and its maps back to the input. Input nodes and cells keep their ids;
/// new ones are appended.
template <class M>
struct PillowResult {
  M mesh;
  IdVector<NodeId, NodeId> node_origin;  ///< the input node each node is (a copy of)
  IdVector<CellId, CellId> cell_origin;  ///< the input cell; for a layer cell, the set's cell
  index_t n_new_nodes = 0;
  index_t n_new_cells = 0;
};

/// Pillows the cells with in_set[c] != 0. `boundary`: boundary_constraints(mesh); `size`:
/// the size criterion on mesh's cells (off by default), which sets the least thickness.
template <class M>
PillowResult<M> pillow_cells(const M& mesh, const IdVector<CellId, char>& in_set,
                             const IdVector<NodeId, NodeConstraint>& boundary,
                             const PillowOptions& options = {}, const SizeCriterion& size = {});

/// The layer cell between a face of a set cell (outward node order) and its copy (the set
/// side): the dimensional part of pillowing.
template <class M>
typename M::CellNodes layer_cell(const typename M::FaceNodes& face,
                                 const typename M::FaceNodes& copy);

}  // namespace hexadapt
