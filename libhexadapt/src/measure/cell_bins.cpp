// Uniform bins over cell bounding boxes (see cell_bins.h).
#include "cell_bins.h"

#include <algorithm>
#include <cmath>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt {

Eigen::AlignedBox3d cell_box(const io::MeshData& mesh, index_t c) {
  Eigen::AlignedBox3d b;
  const auto k = static_cast<std::size_t>(mesh.nodes_per_cell());
  for (std::size_t i = 0; i < k; ++i)
    b.extend(mesh.points[mesh.cells[static_cast<std::size_t>(c) * k + i].idx()]);
  return b;
}

CellBins::CellBins(const io::MeshData& mesh, double bins_per_cell) : dim_(mesh.dim) {
  const index_t n = mesh.n_cells();
  boxes_.resize(static_cast<std::size_t>(n));
  for (index_t c = 0; c < n; ++c) {
    boxes_[static_cast<std::size_t>(c)] = cell_box(mesh, c);
    domain_.extend(boxes_[static_cast<std::size_t>(c)]);
  }
  if (n == 0) return;
  const Eigen::Vector3d ext = domain_.sizes().cwiseMax(1e-300);
  // Bins of equal sides, about bins_per_cell * n of them over the used axes.
  double measure = ext.x() * ext.y() * (dim_ == 3 ? ext.z() : 1.0);
  const double side = std::pow(measure / std::max(1.0, bins_per_cell * n), 1.0 / dim_);
  for (int a = 0; a < dim_; ++a)
    n_[static_cast<std::size_t>(a)] =
        std::clamp(static_cast<int>(std::ceil(ext[a] / side)), 1, 1 << 20);
  size_ = ext.cwiseQuotient(Eigen::Vector3d(n_[0], n_[1], n_[2]));
  const std::size_t n_bins = static_cast<std::size_t>(n_[0]) * static_cast<std::size_t>(n_[1]) *
                             static_cast<std::size_t>(n_[2]);
  start_.assign(n_bins + 1, 0);
  auto each_bin = [&](index_t c, auto&& f) {
    const auto lo = bin_of(boxes_[static_cast<std::size_t>(c)].min());
    const auto hi = bin_of(boxes_[static_cast<std::size_t>(c)].max());
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) f(bin_index(i, j, k));
  };
  for (index_t c = 0; c < n; ++c) each_bin(c, [&](std::size_t b) { ++start_[b + 1]; });
  for (std::size_t b = 0; b < n_bins; ++b) start_[b + 1] += start_[b];
  items_.resize(start_[n_bins]);
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (index_t c = 0; c < n; ++c) each_bin(c, [&](std::size_t b) { items_[fill[b]++] = c; });
}

std::array<int, 3> CellBins::bin_of(const Eigen::Vector3d& p) const {
  std::array<int, 3> b{0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    const double t = std::floor((p[a] - domain_.min()[a]) / size_[a]);
    b[static_cast<std::size_t>(a)] = static_cast<int>(
        std::clamp(t, 0.0, static_cast<double>(n_[static_cast<std::size_t>(a)] - 1)));
  }
  return b;
}

void CellBins::query(const Eigen::AlignedBox3d& q, std::vector<index_t>& out) const {
  out.clear();
  if (items_.empty()) return;
  const Eigen::AlignedBox3d cut = q.intersection(domain_);
  if (cut.isEmpty()) return;
  const auto lo = bin_of(cut.min()), hi = bin_of(cut.max());
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::size_t b = bin_index(i, j, k);
        for (std::size_t s = start_[b]; s < start_[b + 1]; ++s) {
          const index_t c = items_[s];
          const Eigen::AlignedBox3d o = q.intersection(box(c));
          bool overlaps = true;
          for (int a = 0; a < dim_; ++a) overlaps = overlaps && o.max()[a] > o.min()[a];
          if (overlaps) out.push_back(c);
        }
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void CellBins::query_point(const Eigen::Vector3d& p, std::vector<index_t>& out) const {
  out.clear();
  auto holds = [&](const Eigen::AlignedBox3d& b) {
    for (int a = 0; a < dim_; ++a)
      if (!(b.min()[a] <= p[a] && p[a] <= b.max()[a])) return false;
    return true;
  };
  if (items_.empty() || !holds(domain_)) return;
  const auto b = bin_of(p);
  const std::size_t bin = bin_index(b[0], b[1], b[2]);
  for (std::size_t s = start_[bin]; s < start_[bin + 1]; ++s)
    if (holds(box(items_[s]))) out.push_back(items_[s]);
}

}  // namespace hexadapt
