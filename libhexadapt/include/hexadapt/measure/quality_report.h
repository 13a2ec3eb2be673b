// The quality report of hexadapt-measure: what a mesh is worth as a pipeline output.
//
// The paper's method guarantees every output cell a scaled Jacobian >= S_q and a conformal,
// pure mesh (paper sec. 1, sec. 5; DESIGN sec. 4.4 and 6). quality_report() measures exactly
// that on any quad / hex mesh: cell and node counts, min / mean / max scaled Jacobian and
// shape, a histogram over [-1, 1], the cells below the threshold, the mesh check
// (mesh_check.h) and purity (a `material` cell array of valid material indices; with vf_*
// fraction arrays, the number of mixed cells). It works from MeshData so that a mesh whose
// topology the kernels cannot represent (a face shared by more than two cells) is still
// measured and reported as a failed check rather than thrown away.
//
// The report is one section of the measure report; later sections (distances to targets,
// discrepancy against a reference grid) are separate structs with their own JSON sections,
// assembled by the tool (docs/reports.md).
#pragma once

#include <string>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/core/log.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/mesh_check.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {
namespace io {
struct MeshData;
struct GhostedPart;
}  // namespace io

struct QualityReportOptions {
  double threshold = default_threshold;  ///< S_q: cells with scaled Jacobian below it fail
  int bins = 20;                         ///< histogram bins over [-1, 1]
  int max_listed = 10;     ///< how many cells below the threshold (or impure) are listed
  MeshCheckOptions check;  ///< options of the mesh check
  std::string material_array = "material";  ///< cell array of material indices
  std::string fraction_prefix = "vf_";      ///< cell arrays of volume fractions
  double pure_tolerance = 1e-6;  ///< a cell is mixed when its largest fraction is below 1 - this
  /// Called with phase "quality" and the fraction done (cell qualities, then the mesh check,
  /// then purity), ending at 1; nullptr: silent.
  Progress progress;
};

/// Per-cell quality values, indexed by cell.
struct CellQualities {
  std::vector<double> scaled_jacobian;
  std::vector<double> shape;
};

struct QualityStats {
  double min = 0, mean = 0, max = 0;
};

struct QualityHistogram {
  double lo = -1, hi = 1;       ///< bin b covers [lo + b w, lo + (b + 1) w), the last one closed
  std::vector<index_t> counts;  ///< cells per bin
};

struct PurityReport {
  bool has_material = false;           ///< the material array exists
  index_t invalid_material_cells = 0;  ///< not an integer, negative, or >= number of fractions
  std::vector<CellId> first_invalid;
  std::vector<std::string> fraction_arrays;  ///< the vf_* arrays found, in file order
  index_t mixed_cells = 0;  ///< cells whose largest fraction is below 1 - tolerance
  std::vector<CellId> first_mixed;
  bool ok() const { return invalid_material_cells == 0; }
};

struct QualityReport {
  int dim = 0;
  index_t n_cells = 0, n_nodes = 0;
  double threshold = 0;
  QualityStats scaled_jacobian, shape;
  QualityHistogram histogram;
  index_t below_threshold = 0;         ///< cells with scaled Jacobian < threshold
  std::vector<CellIssue> first_below;  ///< the lowest ids among them
  /// Empty when the kernels could build the mesh; otherwise why not (e.g. a face shared by
  /// three cells), and `check` was not run.
  std::string topology_error;
  MeshCheckResult check;
  PurityReport purity;

  bool quality_ok() const { return below_threshold == 0; }
  bool check_ok() const { return topology_error.empty() && check.ok(); }
  /// The pipeline's promise: every cell above the threshold and a valid conformal mesh.
  bool passed() const { return quality_ok() && check_ok(); }
};

/// Scaled Jacobian and shape of every cell of the data (no kernel needed). Throws
/// InputError when a cell refers to a missing node. `progress` (phase "quality") goes from
/// `from` to `to` over the cells.
CellQualities cell_qualities(const io::MeshData& data, const Progress& progress = nullptr,
                             double from = 0.0, double to = 1.0);

/// Measures a mesh given as file data. Throws InputError (no cells, a cell referring to a
/// missing node, a material array with several components) and OptionError (bins < 1).
QualityReport quality_report(const io::MeshData& data, const QualityReportOptions& options = {});
/// The report of a mesh spread over ranks, each holding a part with a ghost layer
/// (io::with_ghost_layers): equal to the report of the whole mesh (ids global), the same on
/// every rank. A part whose cells the kernels cannot represent makes `topology_error` name
/// the rank and the part's local cell ids. Every rank calls it.
QualityReport quality_report(const dist::Communicator& comm, const io::GhostedPart& part,
                             const QualityReportOptions& options = {});
/// The same for a mesh in memory (no arrays: purity is not measured).
QualityReport quality_report(const AnyMesh& mesh, const QualityReportOptions& options = {});

/// The report as a JSON object (text), with the fields of docs/reports.md.
std::string quality_report_json(const QualityReport& report);

}  // namespace hexadapt
