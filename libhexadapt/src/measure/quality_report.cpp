#include "hexadapt/measure/quality_report.h"

#include <algorithm>
#include <cmath>

#include "cell_values.h"
#include "hexadapt/core/error.h"
#include "hexadapt/dist/routing.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_part.h"
#include "purity.h"
#include "rank_figures.h"

namespace hexadapt {

namespace {

QualityHistogram histogram(const dist::Communicator& comm, const std::vector<double>& v, int bins) {
  QualityHistogram h;
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  const double width = (h.hi - h.lo) / bins;
  for (double x : v) {
    const double f = std::floor((x - h.lo) / width);
    const auto b = static_cast<std::size_t>(std::clamp(f, 0.0, double(bins - 1)));
    ++h.counts[b];
  }
  h.counts = summed(comm, std::move(h.counts));
  return h;
}

// The kernels of this rank's part, or why some rank's part has none (then the same reason
// on every rank: the first failing rank's).
std::string build_mesh(const dist::Communicator& comm, const io::MeshData& data, AnyMesh& mesh) {
  std::string error;
  try {
    mesh = io::to_mesh(data);
  } catch (const MeshError& e) {
    error = e.what();
  }
  if (comm.size() == 1) return error;
  dist::Buffer mine;
  mine.put_vector(std::vector<char>(error.begin(), error.end()));
  std::vector<dist::Buffer> all = dist::all_gather(comm, mine);
  for (std::size_t r = 0; r < all.size(); ++r) {
    const std::vector<char> text = all[r].get_vector<char>();
    if (!text.empty())
      return "on the part of rank " + std::to_string(r) + ": " +
             std::string(text.begin(), text.end());
  }
  return "";
}

void run_check(const dist::Communicator& comm, const io::MeshData& data, const PartIds& ids,
               const QualityReportOptions& options, QualityReport& report) {
  AnyMesh mesh;
  report.topology_error = build_mesh(comm, data, mesh);
  if (!report.topology_error.empty()) return;
  report.check =
      std::visit([&](const auto& m) { return check_mesh(comm, m, ids, options.check); }, mesh);
}

QualityReport report_of(const dist::Communicator& comm, const io::MeshData& data,
                        const PartIds& ids, const QualityReportOptions& options) {
  if (options.bins < 1) throw OptionError("the histogram needs at least one bin");
  const index_t owned = ids.owned_cells(data.n_cells());
  if (total(comm, owned) == 0) throw InputError("", "", "the mesh has no quad or hex cells");
  const Progress& progress = options.progress;
  // Shares of the phase, about what each part costs on a hex mesh.
  CellQualities q = cell_qualities(data, progress, 0.0, 0.5);
  q.scaled_jacobian.resize(static_cast<std::size_t>(owned));
  q.shape.resize(static_cast<std::size_t>(owned));
  QualityReport r;
  for (const int d : dist::all_gather_values(comm, std::vector<int>{data.dim}))
    r.dim = std::max(r.dim, d);  // a rank holding no cells may not know it
  r.n_cells = static_cast<index_t>(total(comm, owned));
  std::int64_t owned_nodes = 0;
  for (std::size_t n = 0; n < static_cast<std::size_t>(data.n_points()); ++n)
    owned_nodes += ids.owns_node(n) ? 1 : 0;
  r.n_nodes = static_cast<index_t>(total(comm, owned_nodes));
  r.threshold = options.threshold;
  r.scaled_jacobian = stats(comm, q.scaled_jacobian);
  r.shape = stats(comm, q.shape);
  r.histogram = histogram(comm, q.scaled_jacobian, options.bins);
  for (std::size_t c = 0; c < q.scaled_jacobian.size(); ++c) {
    if (!(q.scaled_jacobian[c] < options.threshold)) continue;
    if (++r.below_threshold <= options.max_listed)
      r.first_below.push_back({CellId(ids.cell(c)), q.scaled_jacobian[c], centroid(data, c)});
  }
  r.below_threshold = static_cast<index_t>(total(comm, r.below_threshold));
  r.first_below = first_of_ranks(comm, std::move(r.first_below), options.max_listed);
  run_check(comm, data, ids, options, r);
  if (progress) progress("quality", 0.9);
  r.purity = measure_purity(comm, data, ids, options);
  if (progress) progress("quality", 1.0);
  return r;
}

}  // namespace

QualityReport quality_report(const io::MeshData& data, const QualityReportOptions& options) {
  return report_of(dist::serial(), data, PartIds(), options);
}

QualityReport quality_report(const dist::Communicator& comm, const io::GhostedPart& part,
                             const QualityReportOptions& options) {
  return report_of(comm, part.part.data, io::part_ids(part), options);
}

QualityReport quality_report(const AnyMesh& mesh, const QualityReportOptions& options) {
  return quality_report(io::from_mesh(mesh), options);
}

}  // namespace hexadapt
