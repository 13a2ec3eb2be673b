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
#include "hexadapt/dist/routing.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_part.h"
#include "locate.h"
#include "rank_figures.h"

namespace hexadapt {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Lower bounds of the histogram bins (docs/reports.md); the last bin is open.
const std::vector<double> edge_ratio_bins = {1, 2, 4, 8, 16, 32, 64, 128};
const std::vector<double> time_step_bins = {0,      1. / 64, 1. / 32, 1. / 16, 1. / 8,
                                            1. / 4, 1. / 2,  1,       2,       4};

SizeHistogram histogram(const dist::Communicator& comm, const std::vector<double>& v,
                        const std::vector<double>& lower) {
  SizeHistogram h{lower, std::vector<index_t>(lower.size(), 0)};
  for (double x : v) {
    const auto above = std::upper_bound(lower.begin(), lower.end(), x) - lower.begin();
    ++h.counts[static_cast<std::size_t>(std::max<std::ptrdiff_t>(above - 1, 0))];
  }
  h.counts = summed(comm, std::move(h.counts));
  return h;
}

// How a rank's part is measured: its ranks, its numbering, its owned cells.
struct Part {
  const dist::Communicator& comm;
  const io::MeshData& data;
  const PartIds& ids;
  std::size_t owned;
};

void time_step_figures(const Part& p, const std::vector<double>& t, SizeFigures& f) {
  f.time_step = stats(p.comm, t);
  const auto lowest = std::min_element(t.begin(), t.end());
  const auto [min, cell] = extreme_with_id(
      p.comm,
      lowest == t.end()
          ? std::pair{0.0, std::int64_t{-1}}
          : std::pair{*lowest, p.ids.cell(static_cast<std::size_t>(lowest - t.begin()))},
      /*highest=*/false);
  f.time_step_min_cell = CellId(cell);
  f.time_step_median = kth_value(p.comm, t, total(p.comm, static_cast<std::int64_t>(t.size())) / 2);
  if (!(f.time_step_median > 0)) return;  // no histogram
  std::vector<double> relative(t.size());
  for (std::size_t c = 0; c < t.size(); ++c) relative[c] = t[c] / f.time_step_median;
  f.time_step_histogram = histogram(p.comm, relative, time_step_bins);
}

std::vector<SizeBreach> first_of_ranks(const dist::Communicator& comm, std::vector<SizeBreach> mine,
                                       int k) {
  return dist::first_of_ranks(
      comm, std::move(mine), static_cast<std::size_t>(std::max(k, 0)),
      [](dist::Buffer& b, const SizeBreach& x) {
        b.put(x.cell);
        for (double v : {x.shortest_edge, x.local_size, x.ratio}) b.put(v);
        b.put_point(x.centroid);
      },
      [](dist::Buffer& b) {
        SizeBreach x;
        x.cell = b.get<CellId>();
        x.shortest_edge = b.get<double>();
        x.local_size = b.get<double>();
        x.ratio = b.get<double>();
        x.centroid = b.get_point();
        return x;
      },
      [](const SizeBreach& a, const SizeBreach& b) { return a.cell < b.cell; });
}

void relative_figures(const Part& p, const CellSizes& s, const std::vector<double>& local,
                      const SizeReportOptions& o, SizeFigures& f) {
  f.has_local_size = true;
  double lowest = inf, highest = 0;
  for (std::size_t c = 0; c < p.owned; ++c) {
    const double shortest = s.edges[c].min / local[c];
    lowest = std::min(lowest, shortest);
    highest = std::max(highest, s.edges[c].max / local[c]);
    if (!(s.edges[c].min < o.min_edge * local[c])) continue;
    if (++f.below_min_edge <= o.max_listed)
      f.first_below.push_back(
          {CellId(p.ids.cell(c)), s.edges[c].min, local[c], shortest, centroid(p.data, c)});
  }
  const std::vector<double> ends =
      dist::all_gather_values(p.comm, std::vector<double>{lowest, highest});
  f.min_relative_edge = inf;
  f.max_relative_edge = 0;
  for (std::size_t r = 0; r < ends.size(); r += 2) {
    f.min_relative_edge = std::min(f.min_relative_edge, ends[r]);
    f.max_relative_edge = std::max(f.max_relative_edge, ends[r + 1]);
  }
  f.below_min_edge = static_cast<index_t>(total(p.comm, f.below_min_edge));
  f.first_below = first_of_ranks(p.comm, std::move(f.first_below), o.max_listed);
}

// The figures of the owned cells; with `local` sizes (on every rank: a rank may hold none).
SizeFigures figures(const Part& p, const CellSizes& s, const std::vector<double>* local,
                    const SizeReportOptions& o) {
  SizeFigures f;
  std::vector<double> ratio(p.owned);
  for (std::size_t c = 0; c < ratio.size(); ++c) ratio[c] = s.edges[c].ratio();
  f.edge_ratio = stats(p.comm, ratio);
  f.edge_ratio_histogram = histogram(p.comm, ratio, edge_ratio_bins);
  time_step_figures(p,
                    std::vector<double>(s.time_step.begin(),
                                        s.time_step.begin() + static_cast<std::ptrdiff_t>(p.owned)),
                    f);
  if (local) relative_figures(p, s, *local, o, f);
  return f;
}

// The array's values, checked on every rank's owned cells: the lowest bad cell id named.
std::vector<double> array_sizes(const Part& p, const io::DataArray& a) {
  if (a.n_components != 1 || a.n_tuples() != static_cast<std::size_t>(p.data.n_cells()))
    throw InputError({}, "cell array '" + a.name + "'", "expected one value per cell");
  std::vector<double> bad{-1.0, 0.0};  // (global cell id, value) of the first bad one
  for (std::size_t c = 0; c < p.owned; ++c)
    if (!(a.values[c] > 0 && a.values[c] < inf)) {
      bad = {double(p.ids.cell(c)), a.values[c]};
      break;
    }
  const std::vector<double> all = dist::all_gather_values(p.comm, bad);
  for (std::size_t r = 0; r < all.size(); r += 2)
    if (all[r] >= 0 && (bad[0] < 0 || all[r] < bad[0])) bad = {all[r], all[r + 1]};
  if (bad[0] >= 0)
    throw InputError({},
                     "cell " + std::to_string(std::int64_t(bad[0])) + " of array '" + a.name + "'",
                     "expected a positive local size, found " + std::to_string(bad[1]));
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
  const PointCells at = frame.is_identity() ? locate(reference, centroids, progress, 0.6, 1.0)
                                            : locate(geometry_in_frame(reference, frame), centroids,
                                                     progress, 0.6, 1.0);
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

void check_inputs(const Part& p, const io::MeshData* reference, const SizeReportOptions& o) {
  if (!(o.min_edge >= 0 && o.min_edge < inf))
    throw OptionError("min_edge must be a number >= 0, not " + std::to_string(o.min_edge));
  if (total(p.comm, static_cast<std::int64_t>(p.owned)) == 0)
    throw InputError({}, {}, "the mesh has no quad or hex cells");
  const io::MeshData& mesh = p.data;
  if (reference && reference->dim != mesh.dim)
    throw InputError({}, {},
                     "the reference grid is " + std::to_string(reference->dim) +
                         "D but the mesh is " + std::to_string(mesh.dim) + "D");
}

// The report of a rank's part (`reference` only on one rank).
SizeReport report_of(const Part& p, const io::MeshData* reference, const SizeReportOptions& o) {
  check_inputs(p, reference, o);
  SizeReport r;
  r.min_edge = o.min_edge;
  // Shares of the phase: the cells' sizes, then locating them in the reference.
  const CellSizes sizes = cell_sizes(p.data, o.progress, 0.0, 0.4);
  CellSizes ref_sizes;
  if (reference) ref_sizes = cell_sizes(*reference, o.progress, 0.4, 0.6);
  std::vector<double> local;
  if (const io::DataArray* a = p.data.find_cell_array(o.local_size_array)) {
    local = array_sizes(p, *a);
    r.local_size = LocalSizeSource::array;
  } else if (reference) {
    local = reference_sizes(p.data, *reference, ref_sizes, o.progress, &r.outside_reference);
    r.local_size = LocalSizeSource::reference;
  }
  if (o.progress) o.progress("size", 1.0);
  r.mesh = figures(p, sizes, r.local_size == LocalSizeSource::none ? nullptr : &local, o);
  if (o.min_edge == 0)
    r.not_checked = "min_edge is 0 (off)";
  else if (r.local_size == LocalSizeSource::none)
    r.not_checked = "no " + o.local_size_array + " array and no reference grid";
  if (!reference) return r;
  r.has_reference = true;
  std::vector<double> own(ref_sizes.edges.size());
  for (std::size_t c = 0; c < own.size(); ++c) own[c] = ref_sizes.edges[c].mean;
  const PartIds whole;
  r.reference = figures({p.comm, *reference, whole, own.size()}, ref_sizes, &own, o);
  r.time_step_ratio = r.reference.time_step.min > 0
                          ? r.mesh.time_step.min / r.reference.time_step.min
                          : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace

SizeReport size_report(const io::MeshData& mesh, const io::MeshData* reference,
                       const SizeReportOptions& o) {
  const PartIds whole;
  return report_of({dist::serial(), mesh, whole, static_cast<std::size_t>(mesh.n_cells())},
                   reference, o);
}

SizeReport size_report(const dist::Communicator& comm, const io::GhostedPart& part,
                       const SizeReportOptions& o) {
  const PartIds ids = io::part_ids(part);
  return report_of({comm, part.part.data, ids, static_cast<std::size_t>(part.owned_cells)}, nullptr,
                   o);
}

}  // namespace hexadapt
