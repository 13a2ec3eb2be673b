#include "hexadapt/adapt/size_criterion.h"

#include <algorithm>
#include <limits>

namespace hexadapt {

SizeCriterion SizeCriterion::remapped(const std::vector<CellId>& origin) const {
  SizeCriterion out{min_edge, {}};
  if (local_size.empty()) return out;
  out.local_size.reserve(origin.size());
  for (CellId c : origin) out.local_size.push_back(local_size[c]);
  return out;
}

template <class M>
IdVector<CellId, double> mean_edge_lengths(const M& grid) {
  IdVector<CellId, double> out(static_cast<std::size_t>(grid.n_cells()), 0.0);
  for (CellId c : id_range<CellId>(grid.n_cells())) out[c] = cell_edge_lengths(grid, c).mean;
  return out;
}

template <class M>
double min_edge_ratio(const M& mesh, const SizeCriterion& size) {
  if (mesh.n_cells() == 0) return 0;
  double ratio = std::numeric_limits<double>::infinity();
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    ratio = std::min(ratio, cell_edge_lengths(mesh, c).min / size.local_size[c]);
  return ratio;
}

template <class M>
double size_ratio(const M& mesh, CellId c, const SizeCriterion& size) {
  if (!size.on()) return std::numeric_limits<double>::infinity();
  return cell_edge_lengths(mesh, c).min / size.min_length(c);
}

template <class M>
std::vector<CellFailure> failing_cells(const M& mesh, double threshold, const SizeCriterion& size) {
  std::vector<CellFailure> out;
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    CellFailure f{c, mesh.cell_quality(c), cell_edge_lengths(mesh, c).min, size.min_length(c),
                  Vec3::Zero()};
    if (!f.shape_failed(threshold) && !f.size_failed()) continue;
    f.centroid = cell_centroid(mesh, c);
    out.push_back(f);
  }
  return out;
}

std::vector<CellFailure> worst_failures(std::vector<CellFailure> failures, std::size_t count) {
  std::stable_sort(
      failures.begin(), failures.end(),
      [](const CellFailure& a, const CellFailure& b) { return a.score() < b.score(); });
  if (failures.size() > count) failures.resize(count);
  return failures;
}

#define HEXADAPT_INSTANTIATE(M)                                          \
  template IdVector<CellId, double> mean_edge_lengths<M>(const M&);      \
  template double min_edge_ratio<M>(const M&, const SizeCriterion&);     \
  template double size_ratio<M>(const M&, CellId, const SizeCriterion&); \
  template std::vector<CellFailure> failing_cells<M>(const M&, double, const SizeCriterion&);
HEXADAPT_INSTANTIATE(QuadMesh)
HEXADAPT_INSTANTIATE(HexMesh)
#undef HEXADAPT_INSTANTIATE

}  // namespace hexadapt
