// Ideal positions of the interface nodes (paper sec. 5, DESIGN 4.3; Sculpt-like, as in the
// reference code).
//
// Interface nodes are the nodes whose cells carry more than one material. For every cell
// next to an interface face, each material's volume-fraction gradient is fitted by weighted
// least squares over the node-neighbour cells (w = 1 / (d^2 + eps), eps = mean(d^2) / 100,
// d the distance between cell centres); a cell on the domain boundary also sees the mirror
// images, across its boundary faces, of itself and of the neighbours touching those faces
// (a symmetric ghost layer, so that fractions constant along the boundary give no tilt).
// On the face between c0 (material m0) and c1 (m1) the interface normal is g_m0(t) - g_m1(t)
// of the gradients interpolated at t = (f_m1(c0) - f_m0(c0)) / d, with
// d = f_m0(c1) - f_m0(c0) - f_m1(c1) + f_m1(c0) (t = 1/2 when |d| is tiny, clamped to
// [0, 1]). The crossing point X is volume-consistent (PLIC-like, mesh/plane_cut.h): in each
// of the two cells whose share of m0 is strictly inside (0, 1), the plane of that normal
// leaving the share of m0 on the m0 side; X is the mean of where those planes cut the
// segment of the cell centres (clamped to the segment). A planar interface is thus found
// exactly. Where one of the two cells is a sheet along the face's axis (a cell whose
// opposite face also faces another material), the mean of the two planes would thin it
// (0.2 / 0.6 / 0.2 across the sheet gives 0.8 cells): X is then the sheet's side with the
// thickness of the material's volume in the three cells of the column, centred on that
// volume's centroid (the outer cells' share against the sheet, the sheet's share in its
// middle; cells of equal length along the axis assumed). When both cells are pure the
// interface is the face itself (its centre and normal). When no plane can be found (degenerate
// cell, plane parallel to the segment) X falls back on the linear crossing at t of the reference
// formula (DESIGN 4.3). A node's target is the mean of its projections onto the planes (2D: lines)
// of its interface faces, then projected onto the domain boundary when the node is on it. In 3D
// each material's targets are then offset along their normal to give it its input volume
// (adapt/target_volume.h).
#pragma once

#include <functional>
#include <vector>

#include "hexadapt/adapt/node_constraint.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt {

/// Where the volume-conserving offset of the targets runs: automatic is 3D only (in 2D the
/// fractions' planes already hold the volumes of the generated cases to 0.01 %, and the
/// offset costs reach on coarse real grids: see docs/results.md).
enum class VolumeOffset { automatic, on, off };

struct TargetOptions {
  double eps_factor = 0.01;        ///< eps = eps_factor * mean(d^2) in the gradient weights
  double tiny_denominator = 1e-5;  ///< |d| below this: the crossing is the face's middle, t = 1/2
  /// An interface normal direction counts for the node's sliding constraint when its weight
  /// is above this share of the strongest one (2D triple points and 3D triple curves).
  double normal_share = 0.2;
  /// Volume-conserving offset of each material's interface (adapt/target_volume.h): where
  /// it runs, sweeps at most, the farthest a target moves in local sizes, and the relative
  /// volume error below which the sweeps stop.
  VolumeOffset volume_offset = VolumeOffset::automatic;
  int volume_sweeps = 8;
  double volume_max_shift = 0.3;
  double volume_tolerance = 1e-5;
};

/// The interface plane found on one face between two materials.
struct InterfaceFace {
  CellId c0, c1;  ///< c0 < c1
  int lf = 0;     ///< local face of c0
  Vec3 point;     ///< crossing point X
  Vec3 normal;    ///< unit normal n
};

struct Targets {
  IdVector<NodeId, char> has;       ///< 1 for the interface nodes
  IdVector<NodeId, Vec3> position;  ///< the target (a node's own position when has == 0)
  /// The interface directions a node must keep to when smoothing slides it along the
  /// interface (empty for non-interface nodes).
  IdVector<NodeId, NodeConstraint> interface;
  std::vector<InterfaceFace> faces;  ///< every interface face, in (c0, lf) order
  index_t n_interface_nodes = 0;
};

/// One process's part of a grid split among processes, for the sums over the whole grid that
/// the volume offset needs (adapt/target_volume.h): the part's cells and nodes this process
/// counts (each cell and node of the grid counted by one process) and how its sums are added
/// to the others'.
struct VolumeParts {
  IdVector<CellId, char> counted_cells;
  IdVector<NodeId, char> counted_nodes;
  /// Replaces every value by its sum over the processes, added in the same order on each.
  std::function<void(std::vector<double>&)> add_up;
};

/// `material` holds one material index per cell (the assignment); `fractions` the volume
/// fractions. `boundary` is the boundary constraint of every node (boundary_constraints()).
/// `parts`: the mesh is one process's part of a grid, with enough cells around the nodes it
/// counts that their targets are the whole grid's (nullptr: the whole grid). Throws InputError
/// when sizes disagree or a material index is out of range.
template <class M>
Targets compute_targets(const M& mesh, const Fractions& fractions, const CellMaterials& material,
                        const IdVector<NodeId, NodeConstraint>& boundary,
                        const TargetOptions& options = {}, const VolumeParts* parts = nullptr);

/// Least-squares gradient of every material's fraction in cell c (one per material).
template <class M>
std::vector<Vec3> fraction_gradients(const M& mesh, const Fractions& fractions, CellId c,
                                     double eps_factor);

/// Each node's boundary constraint plus its interface directions: what smoothing keeps an
/// interface node to, so that it slides along its interface (and the boundary).
IdVector<NodeId, NodeConstraint> sliding_constraints(
    const IdVector<NodeId, NodeConstraint>& boundary, const Targets& targets);

/// Sum over the nodes with a target of |position - target|.
template <class M>
double target_distance(const M& mesh, const Targets& targets);

/// Distance from p to the interface surface at `target`: the plane, line or point through
/// the target that `surface` leaves a node to slide on (sliding_constraints()), i.e. the
/// length of p - target along the constraint's normals (the distance to the target itself
/// when the constraint fixes the node).
double surface_distance(const Vec3& p, const Vec3& target, const NodeConstraint& surface);

/// p's offset from that surface: p minus the nearest point of it (its norm is
/// surface_distance()).
Vec3 surface_offset(const Vec3& p, const Vec3& target, const NodeConstraint& surface);

}  // namespace hexadapt
