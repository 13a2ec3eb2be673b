// The flat picture of a mesh: one polygon per cell in the xy plane. A 2D mesh gives its
// quads; a 3D mesh is cut by the plane z = const and each hex crossing it gives its cut
// polygon. Also the arrows from nodes to their `target` point (the projection targets of
// the paper's sec. 4), for the nodes that lie in the picture.
#pragma once

#include <array>
#include <vector>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::render {

using Point2 = std::array<double, 2>;

struct Polygon {
  std::vector<Point2> points;  ///< convex, in order around the polygon
  index_t cell = 0;            ///< the cell it comes from
};

struct Arrow {
  Point2 from, to;
};

struct SliceOptions {
  double z = 0;  ///< the cutting plane of 3D meshes (unused for 2D)
};

/// One polygon per cell (2D) or per hex crossing z (3D: cells with min z <= z < max z, so
/// a plane through a node layer shows the layer above it). Cells that cut in fewer than
/// three distinct points are left out.
std::vector<Polygon> slice_cells(const io::MeshData& data, const SliceOptions& options);

/// Arrows from each node to its `target` point, for the nodes of the polygons' cells whose
/// z is within half a cell height of the plane (all nodes in 2D). Zero-length arrows are
/// skipped. Empty when the data has no 3-component `target` point array.
std::vector<Arrow> target_arrows(const io::MeshData& data, const std::vector<Polygon>& polygons,
                                 const SliceOptions& options);

}  // namespace hexadapt::render
