// Purity of a mesh's material assignment (part of the quality report).
#pragma once

#include "hexadapt/measure/quality_report.h"

namespace hexadapt {

/// Checks the material array (valid indices) and counts mixed cells of the fraction arrays.
PurityReport measure_purity(const io::MeshData& data, const QualityReportOptions& options);

}  // namespace hexadapt
