// The size report of hexadapt-measure: no slivers (DESIGN sec. 6).
//
// The scaled Jacobian says nothing about size: a cell can be well shaped and still a
// hundred times thinner than the grid it came from, and an explicit Lagrangian solver's
// time step follows the thinnest cell. The adapt stage therefore promises every output cell
// a shortest edge >= min_edge x its local input size. The local size of an input-grid cell
// is its mean edge length (quality/cell_size.h, EdgeLengths::mean); adapt writes on its
// output a cell array `local_size` holding, for each output cell, the local size of the
// input cell it comes from (a pillow layer cell: of the cell it was inflated from).
//
// size_report() takes the local size of each measured cell from that array when the mesh
// has it; otherwise, given a reference grid, it is the mean edge length of the reference
// cell holding the cell's centroid (the nearest reference cell by centroid when none does;
// locate.h in src/); otherwise the sizes relative to the local size are not measured and
// the criterion is not checked. Always: Verdict's edge ratio (longest / shortest edge) and
// the stable time-step length of each cell (cell_size.h) as min / mean / max and histograms
// on fixed bins. With a reference grid, the same figures for the grid itself (each cell's
// local size its own mean edge) and the ratio of the two smallest time-step lengths.
// Every figure is a ratio of lengths or a length: scaling the meshes scales the lengths and
// leaves the ratios and the verdict unchanged.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/core/log.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/measure/quality_report.h"

namespace hexadapt {
namespace io {
struct MeshData;
struct GhostedPart;
}  // namespace io

struct SizeReportOptions {
  /// A cell breaks the size criterion when its shortest edge < min_edge x its local size;
  /// 0: not checked.
  double min_edge = default_min_edge;
  int max_listed = 10;  ///< how many cells breaking the criterion are listed
  std::string local_size_array = "local_size";  ///< cell array of the local input sizes
  /// Called with phase "size" and the fraction done, ending at 1; nullptr: silent.
  Progress progress;
};

/// Where the local sizes of the measured cells came from.
enum class LocalSizeSource { none, array, reference };

/// Counts over fixed bins: bin b covers [lower[b], lower[b + 1]), the last one up to
/// +infinity (included); values below lower[0] count in bin 0.
struct SizeHistogram {
  std::vector<double> lower;
  std::vector<index_t> counts;  ///< empty when the histogram is not defined
};

/// A cell whose shortest edge is below min_edge x its local size.
struct SizeBreach {
  CellId cell;
  double shortest_edge = 0;
  double local_size = 0;
  double ratio = 0;  ///< shortest_edge / local_size
  Vec3 centroid = Vec3::Zero();
};

/// The size figures of one mesh.
struct SizeFigures {
  QualityStats edge_ratio;             ///< longest / shortest edge (+infinity: degenerate)
  SizeHistogram edge_ratio_histogram;  ///< lower bounds 1, 2, 4, ..., 128
  QualityStats time_step;              ///< time-step length (0: inverted or degenerate)
  CellId time_step_min_cell;           ///< the lowest id reaching time_step.min
  double time_step_median = 0;         ///< element floor(n / 2) of the sorted lengths
  /// Of time-step length / median: lower bounds 0, 1/64, 1/32, ..., 1/2, 1, 2, 4; not
  /// defined when the median is 0.
  SizeHistogram time_step_histogram;
  bool has_local_size = false;          ///< the figures below were measured
  double min_relative_edge = 0;         ///< min over cells of shortest edge / local size
  double max_relative_edge = 0;         ///< max over cells of longest edge / local size
  index_t below_min_edge = 0;           ///< cells with shortest edge < min_edge x local size
  std::vector<SizeBreach> first_below;  ///< the lowest ids among them
};

struct SizeReport {
  double min_edge = 0;
  LocalSizeSource local_size = LocalSizeSource::none;
  index_t outside_reference = 0;  ///< source reference: centroids no reference cell holds
  /// Empty when the criterion was checked; otherwise why not.
  std::string not_checked;
  SizeFigures mesh;
  bool has_reference = false;
  SizeFigures reference;  ///< the reference grid's own figures (local size: own mean edge)
  /// mesh.time_step.min / reference.time_step.min (NaN when the latter is 0).
  double time_step_ratio = 0;

  bool checked() const { return not_checked.empty(); }
  /// No cell breaks the criterion (or it was not checked). The reference's cells do not count.
  bool passed() const { return !checked() || mesh.below_min_edge == 0; }
};

/// Measures the sizes of `mesh`, with `reference` (may be nullptr) as the input grid.
/// Throws OptionError (min_edge negative or not finite) and InputError (no cells, a cell
/// referring to a missing node, a reference of another dimension, a local size array with
/// several components or a value that is not a positive number, a cell with no reference
/// cell).
SizeReport size_report(const io::MeshData& mesh, const io::MeshData* reference,
                       const SizeReportOptions& options = {});

/// The same report (no reference grid) of a mesh spread over ranks, each holding a part
/// (io::with_ghost_layers): equal to the report of the whole mesh (ids global), the same on
/// every rank; errors name global cell ids. Every rank calls it.
SizeReport size_report(const dist::Communicator& comm, const io::GhostedPart& part,
                       const SizeReportOptions& options = {});

/// The report as a JSON object (text), fields in docs/reports.md.
std::string size_report_json(const SizeReport& report);

}  // namespace hexadapt
