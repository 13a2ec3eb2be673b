// Reading fractions from a file's cell arrays (or a label map) into Fractions (mesh/fractions.h).
//
// Real solver output is never exact: values slightly below 0 or above 1 and sums off by
// ~1e-6 are normal, and diffuse-interface codes leave a trace (~1e-6) of every material in
// every cell. extract_fractions() therefore validates against tolerances and repairs what is
// within them, and reports what it repaired:
//   - a NaN, or a value below -value_tolerance or above 1 + value_tolerance: InputError;
//   - values within the tolerance are clipped into [0, 1];
//   - values below `zero_below` are set to 0 (traces);
//   - a sum farther than sum_tolerance from 1: InputError, unless a void material is named,
//     which receives the remainder 1 - sum (a sum above 1 + sum_tolerance is still an error);
//   - every cell is then rescaled to sum exactly 1 (a cell left with all zeros is an error).
// sum_tolerance and zero_below follow the precision the arrays were stored in unless the
// options give them (mesh/fraction_tolerances.h); the report says which values were used and why.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hexadapt/dist/block.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/fraction_tolerances.h"
#include "hexadapt/mesh/fractions.h"

namespace hexadapt::io {

struct FractionOptions {
  /// Cell arrays to read, in order; empty: every cell array named vf_<material>, in file order.
  /// An entry that names no array but holds commas lists the names between them ("vf_a,vf_b");
  /// one naming an array is that array, commas or spaces in its name included.
  std::vector<std::string> arrays;
  /// If not empty, a material of this name receives 1 - sum of the others: a new material
  /// after them, or, when an array of that material is among them (vf_<name>), that
  /// material in its place, recomputed instead of read.
  std::string void_material;
  double value_tolerance = 1e-4;  ///< how far outside [0,1] a value may be and still be clipped
  /// How far from 1 a cell's sum may be and still be rescaled; unset: decided from the
  /// stored precision (decide_tolerances: 1e-4, for float32 data at least 8 n FLT_EPSILON).
  std::optional<double> sum_tolerance;
  /// Fractions below this are traces and become 0; unset: decided from the stored precision
  /// (decide_tolerances: 1e-5, for float32 data at least 8 n FLT_EPSILON).
  std::optional<double> zero_below;
  /// A label map instead of fraction arrays: this integer cell array gives each cell's
  /// material; every distinct value is one material (fraction 1 in its cells), in increasing
  /// order of value. Exclusive with `arrays` and `void_material`.
  std::string labels;
  /// Names of label values; a value not listed is named label_<value>.
  std::map<std::int64_t, std::string> label_names;
  /// More distinct labels is an error (fractions are dense: cells x materials).
  int max_labels = 1000;
  /// When the data is one block of a distributed grid: the labels of the whole grid,
  /// increasing (label_values of every block, merged), which are its materials. Empty: the
  /// labels the data holds.
  std::vector<std::int64_t> label_values;
};

struct FractionReport {
  index_t clipped_values = 0;  ///< values moved into [0, 1]
  index_t zeroed_values = 0;   ///< traces set to 0
  index_t rescaled_cells = 0;  ///< cells whose sum was not 1 (to 1e-12) before rescaling
  double max_sum_error = 0;    ///< largest |sum - 1| seen before repair
  /// float32 when at least one array read was stored as float32 (a recomputed void
  /// material's array is not read); float64 for label maps.
  StoredPrecision precision = StoredPrecision::float64;
  /// The sum tolerance and trace threshold used, given or decided from `precision`.
  FractionTolerances tolerances;
};

/// Reads the fraction arrays of `data` (file name `file` only for error messages), or the
/// label map when options.labels is set. A sum outside the tolerance is an InputError naming
/// the cell, its sum and the --sum-tolerance that would accept it and every cell of the file.
/// When `block` is given, `data` is one rank's block of a distributed grid (dist/block.h):
/// the report counts the cells it owns only, errors name cells by their global id, and a
/// label map needs options.label_values (its materials are the values of the whole grid; an
/// OptionError without them).
Fractions extract_fractions(const MeshData& data, const FractionOptions& options,
                            FractionReport* report = nullptr, const std::string& file = {},
                            const dist::Block* block = nullptr);

/// The materials of a label map: options.labels names an integer cell array (any numeric
/// type, values exact integers); one material per distinct value in increasing order, named
/// by options.label_names or label_<value>. Throws InputError (no such array, several
/// components, a value that is not an integer, too many labels: naming the file, array and
/// cell), OptionError (fraction arrays or a void material given too, two labels of one name).
/// With options.label_values, those are the materials (a block's cells hold some of them);
/// `block` is the part of the whole grid data holds (if any), naming cells in errors.
Fractions fractions_from_labels(const MeshData& data, const FractionOptions& options,
                                const std::string& file = {}, const dist::Block* block = nullptr);

/// The distinct values of the label map options.labels in data's cells, increasing; errors
/// as fractions_from_labels', naming cells by their id in `block`'s whole grid.
std::vector<std::int64_t> label_values(const MeshData& data, const FractionOptions& options,
                                       const std::string& file = {},
                                       const dist::Block* block = nullptr);

}  // namespace hexadapt::io
