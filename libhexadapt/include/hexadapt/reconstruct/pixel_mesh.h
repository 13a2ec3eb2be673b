// The sub-pixel mesh of interface reconstruction (paper sec. 4.1, DESIGN sec. 4.2).
//
// Every mixed coarse cell, and every cell sharing a node with one, is split into nsub^d
// pixels by the bilinear (2D) or trilinear (3D) map of its corners, so pixels of an
// unstructured cell have different volumes (the paper's Fig. 8 situation). Pixels of mixed
// cells are free; pixels of pure cells are fixed to the material the assignment gives the
// cell. Pixels are stored per coarse-cell block: pixel p of block b has index
// b * nsub^d + local, local = i + nsub * (j + nsub * k). Neighbours inside a block follow from
// index arithmetic, across blocks through one precomputed link per block face (the coarse
// kernel's neighbour() plus the matching of the shared face's nodes), so non-Cartesian and
// arbitrarily oriented conforming meshes work. Cells that are not pixelated are pure and
// take their assigned material; they have no pixels.
//
// The memory the pixels need is estimated before anything is allocated and the build is
// refused (ResourceError) beyond PixelOptions::max_memory: memory is the known limit of
// these methods (paper sec. 4.2).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hexadapt/core/geometry.h"
#include "hexadapt/core/ids.h"
#include "hexadapt/dist/block.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::reconstruct {

struct PixelOptions {
  /// Pixels per axis and coarse cell; 0 picks 10 in 2D and 4 in 3D.
  int nsub = 0;
  /// Bytes the pixels and the method's working arrays may use; the build refuses beyond.
  double max_memory = 8e9;
  /// Working bytes the chosen method needs per free pixel (added to the estimate).
  double method_bytes_per_free_pixel = 0;
  /// Bytes per pixel of an output written afterwards (the pixel mesh file), 0 if none.
  double output_bytes_per_pixel = 0;
};

/// Counts and the memory estimate of a pixel mesh, computed before allocating.
struct PixelPlan {
  int dim = 0;
  int nsub = 0;
  index_t n_blocks = 0;       ///< pixelated coarse cells
  index_t n_free_blocks = 0;  ///< mixed coarse cells
  std::int64_t n_pixels = 0;
  std::int64_t n_free_pixels = 0;
  double bytes = 0;  ///< estimated peak bytes of the pixels plus the method's arrays
};

/// One face of a block glued to the neighbouring block: how lattice coordinates map across.
struct FaceLink {
  index_t block = -1;  ///< the neighbouring block, -1 on the domain boundary or a plain cell
  /// Per axis of the neighbour: the source axis of this block, or -1 for the constant axis.
  std::array<std::int8_t, 3> axis{{-1, -1, -1}};
  /// Per axis of the neighbour: 1 when the coordinate runs backwards (or the constant is the
  /// last layer), 0 otherwise.
  std::array<std::int8_t, 3> flip{{0, 0, 0}};
};

class PixelMesh {
 public:
  /// Pixel label of a free pixel no method has assigned yet.
  static constexpr int unassigned = -1;

  PixelMesh() = default;
  PixelMesh(int dim, int nsub, int n_materials, const std::vector<CellId>& block_cells,
            const std::vector<std::uint8_t>& block_free, index_t n_cells);

  int dim() const { return dim_; }
  int nsub() const { return nsub_; }
  int n_materials() const { return n_materials_; }
  index_t pixels_per_block() const { return ppb_; }
  index_t n_blocks() const { return static_cast<index_t>(cells_.size()); }
  /// The cells of the mesh the pixels were built on.
  index_t n_cells() const { return static_cast<index_t>(cell_block_.size()); }
  std::int64_t n_pixels() const { return static_cast<std::int64_t>(label_.size()); }

  CellId block_cell(index_t b) const { return cells_[static_cast<std::size_t>(b)]; }
  /// The block of a coarse cell, -1 when the cell is not pixelated.
  index_t cell_block(CellId c) const { return cell_block_[c]; }
  bool block_free(index_t b) const { return free_[static_cast<std::size_t>(b)] != 0; }
  index_t pixel_block(std::int64_t p) const { return static_cast<index_t>(p / ppb_); }
  std::int64_t first_pixel(index_t b) const { return static_cast<std::int64_t>(b) * ppb_; }
  bool pixel_free(std::int64_t p) const { return block_free(pixel_block(p)); }

  /// Lattice coordinates (i, j, k) of pixel p inside its block (k = 0 in 2D).
  std::array<int, 3> lattice(std::int64_t p) const;
  std::int64_t pixel_at(index_t b, const std::array<int, 3>& ijk) const;
  /// The pixel across local face lf of pixel p (ref-cell face order), -1 if none.
  std::int64_t neighbour(std::int64_t p, int lf) const;
  int faces_per_pixel() const { return 2 * dim_; }

  double volume(std::int64_t p) const { return volume_[static_cast<std::size_t>(p)]; }
  /// Position of lattice point L (coordinates in [0, nsub]) of block b.
  Vec3 lattice_point(index_t b, const std::array<double, 3>& L) const;
  Vec3 centre(std::int64_t p) const;
  /// Mean pixel width (volume^(1/d)): the length unit of the distance-based energies.
  double mean_width() const { return mean_width_; }

  int label(std::int64_t p) const { return label_[static_cast<std::size_t>(p)]; }
  void set_label(std::int64_t p, int m) { label_[static_cast<std::size_t>(p)] = m; }
  const std::vector<int>& labels() const { return label_; }
  std::vector<int>& labels() { return label_; }

  // Filled by the builder.
  std::vector<Vec3>& block_corners() { return corners_; }
  std::vector<FaceLink>& block_links() { return links_; }
  std::vector<double>& volumes() { return volume_; }
  void set_mean_width(double w) { mean_width_ = w; }
  const FaceLink& link(index_t b, int lf) const {
    return links_[static_cast<std::size_t>(b) * static_cast<std::size_t>(2 * dim_) +
                  static_cast<std::size_t>(lf)];
  }

 private:
  int dim_ = 0, nsub_ = 0, n_materials_ = 0;
  index_t ppb_ = 0;
  std::vector<CellId> cells_;
  std::vector<std::uint8_t> free_;
  IdVector<CellId, index_t> cell_block_;
  std::vector<Vec3> corners_;    ///< nodes_per_cell corner points per block
  std::vector<FaceLink> links_;  ///< faces_per_cell links per block
  std::vector<double> volume_;
  std::vector<int> label_;
  double mean_width_ = 1;
};

/// nsub when PixelOptions::nsub is 0: 10 in 2D, 4 in 3D.
int default_nsub(int dim);

/// Counts pixels and estimates memory without allocating them. `assignment` gives each
/// coarse cell's material. Throws InputError when sizes or materials are inconsistent,
/// OptionError for nsub out of [1, 64].
template <class M>
PixelPlan plan_pixels(const M& mesh, const Fractions& fractions, const CellMaterials& assignment,
                      const PixelOptions& options);

/// The plan's estimate split over the cells `block` owns, in their order: a cell's share of
/// the bytes (its pixels and block arrays when pixelated, the method's arrays too when
/// mixed). On the whole mesh they add up to plan_pixels' bytes; on a rank's part, the
/// owned cells' shares are exact when the part holds one layer of cells around them (which
/// cells are pixelated depends on their neighbours). Throws as plan_pixels.
template <class M>
std::vector<double> owned_cell_bytes(const M& mesh, const Fractions& fractions,
                                     const CellMaterials& assignment, const PixelOptions& options,
                                     const dist::Block& block);

/// Builds the pixel mesh; fixed pixels get their cell's assigned material, free ones
/// PixelMesh::unassigned. Throws ResourceError when the plan exceeds options.max_memory.
template <class M>
PixelMesh build_pixel_mesh(const M& mesh, const Fractions& fractions,
                           const CellMaterials& assignment, const PixelOptions& options,
                           PixelPlan* plan = nullptr);

/// Throws ResourceError when the plan needs more than options.max_memory (as build_pixel_mesh).
void check_pixel_memory(const PixelPlan& plan, const PixelOptions& options);

/// The plan of the pixels of a mesh spread over ranks (`pixels` built on this rank's part):
/// the blocks of the cells every rank owns, and the estimate of one process holding them all.
/// Every rank calls it.
PixelPlan whole_plan(const PixelMesh& pixels, const PixelOptions& options,
                     const dist::Distribution& where);

/// The face link from local face lf of coarse cell c to its neighbour (block left at -1).
template <class M>
FaceLink face_link(const M& mesh, CellId c, int lf);

}  // namespace hexadapt::reconstruct
