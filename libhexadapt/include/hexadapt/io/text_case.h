// The plain text formats of small hand-made cases (DESIGN sec. 7.1), compatible with the
// reference implementation's test inputs: the structured "internal format" (unit cells,
// origin 0) and the unstructured 2D "unstruct format". Fractions become cell arrays
// vf_<material name>, in the order the materials are first listed. The structured format
// may hold several blocks, each a list of materials with their cells; as the reference reads
// them, a material is known by its name, and a later block lists more of its cells (a cell
// listed twice for one material is an error).
#pragma once

#include <string>
#include <string_view>

#include "hexadapt/io/mesh_data.h"

namespace hexadapt::io {

/// Parses either format (told apart by its layout); `file` names it in error messages,
/// which give the line. Throws InputError for wrong counts, indices out of range, fractions
/// that are not numbers and truncated files. Values outside [0, 1] and sums other than 1 are
/// kept as written: extract_fractions judges them with its tolerances, as for every format.
MeshData read_text_case(std::string_view content, const std::string& file);

}  // namespace hexadapt::io
