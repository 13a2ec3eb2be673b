// A uniform grid of bins over the bounding boxes of a mesh's cells: the candidate search
// of the imprint and of the cell containing a point. Each cell is listed in every bin its box
// overlaps (CSR storage, built serially so the lists are in increasing cell order).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "hexadapt/core/ids.h"

namespace hexadapt {
namespace io {
struct MeshData;
}

class CellBins {
 public:
  CellBins(const io::MeshData& mesh, double bins_per_cell);
  const Eigen::AlignedBox3d& box(index_t cell) const {
    return boxes_[static_cast<std::size_t>(cell)];
  }
  /// Cells whose box overlaps `q` with positive volume (area in 2D), increasing ids, into
  /// `out` (overwritten).
  void query(const Eigen::AlignedBox3d& q, std::vector<index_t>& out) const;
  /// Cells whose closed box holds `p` (over the mesh's dimensions), increasing ids, into
  /// `out` (overwritten).
  void query_point(const Eigen::Vector3d& p, std::vector<index_t>& out) const;
  /// The box of all the cells.
  const Eigen::AlignedBox3d& domain() const { return domain_; }

 private:
  int dim_ = 3;
  std::vector<Eigen::AlignedBox3d> boxes_;
  Eigen::AlignedBox3d domain_;
  std::array<int, 3> n_{1, 1, 1};
  Eigen::Vector3d size_;
  std::vector<std::size_t> start_;
  std::vector<index_t> items_;
  std::array<int, 3> bin_of(const Eigen::Vector3d& p) const;
  std::size_t bin_index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(n_[1]) +
            static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(n_[0]) +
           static_cast<std::size_t>(i);
  }
};

/// The bounding box of cell c of the data.
Eigen::AlignedBox3d cell_box(const io::MeshData& mesh, index_t c);

}  // namespace hexadapt
