#include "hexadapt/measure/quality_report.h"

#include <algorithm>
#include <cmath>

#include "cell_values.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_data.h"
#include "purity.h"

namespace hexadapt {

namespace {

QualityHistogram histogram(const std::vector<double>& v, int bins) {
  QualityHistogram h;
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  const double width = (h.hi - h.lo) / bins;
  for (double x : v) {
    const double f = std::floor((x - h.lo) / width);
    const auto b = static_cast<std::size_t>(std::clamp(f, 0.0, double(bins - 1)));
    ++h.counts[b];
  }
  return h;
}

void run_check(const io::MeshData& data, const QualityReportOptions& options,
               QualityReport& report) {
  AnyMesh mesh;
  try {
    mesh = io::to_mesh(data);
  } catch (const MeshError& e) {
    report.topology_error = e.what();
    return;
  }
  report.check = std::visit([&](const auto& m) { return check_mesh(m, options.check); }, mesh);
}

}  // namespace

QualityReport quality_report(const io::MeshData& data, const QualityReportOptions& options) {
  if (options.bins < 1) throw OptionError("the histogram needs at least one bin");
  if (data.n_cells() == 0) throw InputError("", "", "the mesh has no quad or hex cells");
  const Progress& progress = options.progress;
  // Shares of the phase, about what each part costs on a hex mesh.
  const CellQualities q = cell_qualities(data, progress, 0.0, 0.5);
  QualityReport r;
  r.dim = data.dim;
  r.n_cells = data.n_cells();
  r.n_nodes = data.n_points();
  r.threshold = options.threshold;
  r.scaled_jacobian = stats(q.scaled_jacobian);
  r.shape = stats(q.shape);
  r.histogram = histogram(q.scaled_jacobian, options.bins);
  for (std::size_t c = 0; c < q.scaled_jacobian.size(); ++c) {
    if (!(q.scaled_jacobian[c] < options.threshold)) continue;
    if (++r.below_threshold <= options.max_listed)
      r.first_below.push_back({CellId(c), q.scaled_jacobian[c], centroid(data, c)});
  }
  run_check(data, options, r);
  if (progress) progress("quality", 0.9);
  r.purity = measure_purity(data, options);
  if (progress) progress("quality", 1.0);
  return r;
}

QualityReport quality_report(const AnyMesh& mesh, const QualityReportOptions& options) {
  return quality_report(io::from_mesh(mesh), options);
}

}  // namespace hexadapt
