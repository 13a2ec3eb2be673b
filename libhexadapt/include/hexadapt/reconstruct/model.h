// The geometric model extracted from a pixel assignment (paper sec. 4, DESIGN sec. 4.2): the
// interfaces between pixels of different materials, as segments (2D) or quads (3D) tagged
// with their material pair, plus the feature curves (3D) and corners where three or more
// materials meet or an interface reaches the domain boundary. The adapt stage smooths and
// projects target positions onto it (paper sec. 5.3).
//
// Cells that are not pixelated count as nsub^d pixels of their assigned material, so
// interfaces between two pure cells appear too and the model is conforming: every vertex is
// a lattice point of a coarse cell, identified exactly by its integer trilinear weights on
// the coarse nodes, so the two cells of a shared face produce the same vertices. Each
// material's interfaces are thus watertight inside the domain; they are open only on the
// domain boundary, which is not part of the model.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/mesh/fractions.h"
#include "hexadapt/reconstruct/pixel_mesh.h"

namespace hexadapt::reconstruct {

struct InterfaceModel {
  int dim = 0;
  std::vector<Vec3> points;
  /// 2D: segments (first two ids), lo material on the left; 3D: quads whose right-hand
  /// normal points from the lo material to the hi one.
  std::vector<std::array<index_t, 4>> facets;
  std::vector<std::array<int, 2>> facet_materials;  ///< {lo, hi}, lo < hi
  std::vector<std::array<index_t, 2>> curves;       ///< 3D feature edges
  std::vector<index_t> corners;                     ///< feature points
  int nodes_per_facet() const { return dim == 3 ? 4 : 2; }
};

/// Extracts the model of the pixel assignment; `assignment` gives the material of cells
/// without pixels.
template <class M>
InterfaceModel extract_model(const M& mesh, const PixelMesh& pixels,
                             const CellMaterials& assignment);

/// Area (2D) or volume (3D) enclosed by the facets bounding `material` (divergence theorem,
/// exact for the bilinear pixel faces). Meaningful when the material does not reach the
/// domain boundary.
double enclosed_volume(const InterfaceModel& model, int material);

/// Directed facet edges (3D) or endpoints (2D) of `material`'s boundary that have no
/// matching opposite: 0 when its interfaces are closed.
std::int64_t open_boundary_count(const InterfaceModel& model, int material);

}  // namespace hexadapt::reconstruct
