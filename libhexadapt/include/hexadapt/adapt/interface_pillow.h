// Quality-controlled pillowing of the interfaces before the first move (guaranteed method).
//
// In 3D a node of the input grid's staircase is a corner of up to eight cells of two or more
// materials: moving it onto a smooth interface flattens some of them, and the controlled move
// (sec. 5.1) refuses, so most nodes stay on the staircase. Sculpt pillows every interface
// before it smooths; the paper pillows cavities after the move (sec. 5.2), only around the
// nodes left short. Here each material's region is pillowed first, on the unmoved grid, as
// the base method's global pillowing does (pillow.h): every interface node then only touches
// layer cells, which bend where the grid's cells would fold. Unlike the base method, a
// material's layer is kept only when every cell keeps the criteria (threshold and size,
// size_criterion.h) once the new nodes are smoothed. Where cells fail (around the
// staircase's concave corners, in sheets one cell thick), the cells of the region within
// vertex distance `carve` of each failing cell's origin are left out of the pillowed set and
// the material is pillowed again, at most `rounds` times; then it is left unpillowed. Where
// what is left of the region touches itself along an edge in a way no layer can follow
// (pillow.h), the cells around such edges are carved out the same way. Nodes with a target
// never move here; the cells outside a kept layer and its ring are the input's. The cells
// around a frozen node (BoundaryOptions::frozen) are left out of every set from the start,
// unless pillow_frozen: then they are pillowed as the others, and a frozen node's copies,
// placed as a free node's, smoothed among themselves (every other node held) and frozen.
//
// A cell one cell thick between two other materials (across two facing faces), as in the wedge
// of air where a drop meets a pool, is left out of its material's layer from the start: with
// a layer on both of its interfaces, three cells would lie across a sheet thinner than one,
// and the nodes there could reach neither interface within the threshold and the size
// criterion (`sheet_layers` pillows them too).
//
// With `keep_failing`, a layer is kept at its first pillowing even where cells fail: on the
// staircase a layer cell at a concave corner is sheared, and the moves that bring the
// interface nodes onto their smooth surface often mend it (the controlled move makes no
// passing cell fail nor a failing one worse, the smoothing no passing cell fail). The caller
// then checks the cells, and pillows again with the regions around what stayed failing left
// out (`left_out_around`: input cells, carved like failing cells before the first pillowing).
#pragma once

#include <vector>

#include "hexadapt/adapt/pillow.h"
#include "hexadapt/adapt/size_criterion.h"
#include "hexadapt/adapt/smoothing.h"
#include "hexadapt/adapt/step_settings.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

struct InterfacePillowOptions {
  int rounds = 4;             ///< pillowing attempts per material
  int carve = 0;              ///< vertex distance of the cells left out around a failing cell
  bool keep_failing = false;  ///< keep a layer at its first pillowing, failing cells and all
  /// Pillow the cells one cell thick between two other materials too (off: they are left out
  /// of their material's layer from the start).
  bool sheet_layers = false;
};

/// What happened to one material.
struct InterfacePillowAttempt {
  int material = 0;
  int rounds = 0;           ///< pillowings tried
  bool kept = false;        ///< its layer is in the mesh
  index_t left_out = 0;     ///< cells of the region carved out of the pillowed set
  index_t sheet_cells = 0;  ///< of those, cells one cell thick between two other materials
  index_t layer_cells = 0;  ///< cells of the kept layer
  index_t failing = 0;      ///< cells of the kept layer and its ring below a criterion
};

template <class M>
struct InterfacePillowResult {
  M mesh;
  CellMaterials material;
  IdVector<CellId, CellId> cell_origin;  ///< the input cell; a layer cell: its region's cell
  IdVector<NodeId, NodeId> node_origin;  ///< the input node each node is (a copy of)
  index_t n_new_nodes = 0;               ///< appended after the input's nodes
  std::vector<InterfacePillowAttempt> attempts;
};

/// `fixed`: one flag per node of mesh, nodes that must not move (those with a target); `size`:
/// the size criterion on mesh's cells; a layer is kept when its cells reach shared.threshold
/// and the size criterion; `left_out_around`: cells of mesh around which (within vertex
/// distance `carve`) no region is pillowed.
template <class M>
InterfacePillowResult<M> pillow_interfaces(const M& mesh, const CellMaterials& material,
                                           int n_materials, const IdVector<NodeId, char>& fixed,
                                           const SizeCriterion& size,
                                           const InterfacePillowOptions& options = {},
                                           const StepSettings& shared = {},
                                           const std::vector<CellId>& left_out_around = {});

}  // namespace hexadapt
