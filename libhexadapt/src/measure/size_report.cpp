// The size report: local sizes, edge ratio, time-step length and the min-edge criterion
// (see size_report.h).
#include "hexadapt/measure/size_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cell_sizes.h"
#include "cell_values.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "locate.h"

namespace hexadapt {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Lower bounds of the histogram bins (docs/reports.md); the last bin is open.
const std::vector<double> edge_ratio_bins = {1, 2, 4, 8, 16, 32, 64, 128};
const std::vector<double> time_step_bins = {0,      1. / 64, 1. / 32, 1. / 16, 1. / 8,
                                            1. / 4, 1. / 2,  1,       2,       4};

SizeHistogram histogram(const std::vector<double>& v, const std::vector<double>& lower) {
  SizeHistogram h{lower, std::vector<index_t>(lower.size(), 0)};
  for (double x : v) {
    const auto above = std::upper_bound(lower.begin(), lower.end(), x) - lower.begin();
    ++h.counts[static_cast<std::size_t>(std::max<std::ptrdiff_t>(above - 1, 0))];
  }
  return h;
}

void time_step_figures(const std::vector<double>& t, SizeFigures& f) {
  f.time_step = stats(t);
  f.time_step_min_cell =
      CellId(static_cast<index_t>(std::min_element(t.begin(), t.end()) - t.begin()));
  std::vector<double> sorted = t;
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  f.time_step_median = *mid;
  if (!(f.time_step_median > 0)) return;  // no histogram
  std::vector<double> relative(t.size());
  for (std::size_t c = 0; c < t.size(); ++c) relative[c] = t[c] / f.time_step_median;
  f.time_step_histogram = histogram(relative, time_step_bins);
}

void relative_figures(const io::MeshData& data, const CellSizes& s,
                      const std::vector<double>& local, const SizeReportOptions& o,
                      SizeFigures& f) {
  f.has_local_size = true;
  f.min_relative_edge = inf;
  f.max_relative_edge = 0;
  for (std::size_t c = 0; c < local.size(); ++c) {
    const double shortest = s.edges[c].min / local[c];
    f.min_relative_edge = std::min(f.min_relative_edge, shortest);
    f.max_relative_edge = std::max(f.max_relative_edge, s.edges[c].max / local[c]);
    if (!(s.edges[c].min < o.min_edge * local[c])) continue;
    if (++f.below_min_edge <= o.max_listed)
      f.first_below.push_back(
          {CellId(static_cast<index_t>(c)), s.edges[c].min, local[c], shortest, centroid(data, c)});
  }
}

SizeFigures figures(const io::MeshData& data, const CellSizes& s, const std::vector<double>& local,
                    const SizeReportOptions& o) {
  SizeFigures f;
  std::vector<double> ratio(s.edges.size());
  for (std::size_t c = 0; c < ratio.size(); ++c) ratio[c] = s.edges[c].ratio();
  f.edge_ratio = stats(ratio);
  f.edge_ratio_histogram = histogram(ratio, edge_ratio_bins);
  time_step_figures(s.time_step, f);
  if (!local.empty()) relative_figures(data, s, local, o, f);
  return f;
}

std::vector<double> array_sizes(const io::MeshData& mesh, const io::DataArray& a) {
  if (a.n_components != 1 || a.n_tuples() != static_cast<std::size_t>(mesh.n_cells()))
    throw InputError({}, "cell array '" + a.name + "'", "expected one value per cell");
  for (std::size_t c = 0; c < a.values.size(); ++c)
    if (!(a.values[c] > 0 && a.values[c] < inf))
      throw InputError({}, "cell " + std::to_string(c) + " of array '" + a.name + "'",
                       "expected a positive local size, found " + std::to_string(a.values[c]));
  return a.values;
}

// The mean edge of the reference cell holding each cell's centroid.
std::vector<double> reference_sizes(const io::MeshData& mesh, const io::MeshData& reference,
                                    const CellSizes& grid_sizes, const Progress& progress,
                                    index_t* outside) {
  const UnitFrame frame = far_unit_frame(reference.points);
  std::vector<Vec3> centroids(static_cast<std::size_t>(mesh.n_cells()));
  for (std::size_t c = 0; c < centroids.size(); ++c)
    centroids[c] = frame.to_local(centroid(mesh, c));
  const PointCells at =
      frame.is_identity() ? locate(reference, centroids, progress, 0.6, 1.0)
                          : locate(geometry_in_frame(reference, frame), centroids, progress, 0.6, 1.0);
  *outside = at.outside;
  std::vector<double> local(centroids.size());
  for (std::size_t c = 0; c < local.size(); ++c) {
    const index_t r = at.cell[c];
    local[c] = r >= 0 ? grid_sizes.edges[static_cast<std::size_t>(r)].mean : 0.0;
    if (!(local[c] > 0))
      throw InputError({}, "cell " + std::to_string(c),
                       r >= 0 ? "its reference cell " + std::to_string(r) + " has no size"
                              : "no reference cell near its centroid");
  }
  return local;
}

void check_inputs(const io::MeshData& mesh, const io::MeshData* reference,
                  const SizeReportOptions& o) {
  if (!(o.min_edge >= 0 && o.min_edge < inf))
    throw OptionError("min_edge must be a number >= 0, not " + std::to_string(o.min_edge));
  if (mesh.n_cells() == 0) throw InputError({}, {}, "the mesh has no quad or hex cells");
  if (reference && reference->dim != mesh.dim)
    throw InputError({}, {},
                     "the reference grid is " + std::to_string(reference->dim) +
                         "D but the mesh is " + std::to_string(mesh.dim) + "D");
}

}  // namespace

SizeReport size_report(const io::MeshData& mesh, const io::MeshData* reference,
                       const SizeReportOptions& o) {
  check_inputs(mesh, reference, o);
  SizeReport r;
  r.min_edge = o.min_edge;
  // Shares of the phase: the cells' sizes, then locating them in the reference.
  const CellSizes sizes = cell_sizes(mesh, o.progress, 0.0, 0.4);
  CellSizes ref_sizes;
  if (reference) ref_sizes = cell_sizes(*reference, o.progress, 0.4, 0.6);
  std::vector<double> local;
  if (const io::DataArray* a = mesh.find_cell_array(o.local_size_array)) {
    local = array_sizes(mesh, *a);
    r.local_size = LocalSizeSource::array;
  } else if (reference) {
    local = reference_sizes(mesh, *reference, ref_sizes, o.progress, &r.outside_reference);
    r.local_size = LocalSizeSource::reference;
  }
  if (o.progress) o.progress("size", 1.0);
  r.mesh = figures(mesh, sizes, local, o);
  if (o.min_edge == 0)
    r.not_checked = "min_edge is 0 (off)";
  else if (local.empty())
    r.not_checked = "no " + o.local_size_array + " array and no reference grid";
  if (!reference) return r;
  r.has_reference = true;
  std::vector<double> own(ref_sizes.edges.size());
  for (std::size_t c = 0; c < own.size(); ++c) own[c] = ref_sizes.edges[c].mean;
  r.reference = figures(*reference, ref_sizes, own, o);
  r.time_step_ratio = r.reference.time_step.min > 0
                          ? r.mesh.time_step.min / r.reference.time_step.min
                          : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace hexadapt
