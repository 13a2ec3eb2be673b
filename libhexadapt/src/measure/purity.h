// Purity of a mesh's material assignment (part of the quality report).
#pragma once

#include "hexadapt/dist/communicator.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/mesh/part_ids.h"

namespace hexadapt {

/// Checks the material array (valid indices) and counts mixed cells of the fraction arrays,
/// over the cells every rank owns (`data` a rank's part numbered by `ids`). Every rank
/// calls it.
PurityReport measure_purity(const dist::Communicator& comm, const io::MeshData& data,
                            const PartIds& ids, const QualityReportOptions& options);

}  // namespace hexadapt
