// How a stage read its input grid's fractions, carried from stage to stage: assign records
// the flags it read with and the tolerances it decided (hexadapt_input, a JSON object in the
// mesh's metadata), adapt and reconstruct pass it on, and measure reads its --reference the
// same way when no reading flag is given, so that --sum-tolerance, --void, --fractions and
// the rest need not be repeated at every stage.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::cli {

/// The metadata key of the record.
inline constexpr const char* input_record_key = "hexadapt_input";

/// The record of reading with `in`, the tolerances being those `report` says were used.
std::string input_record(const InputOptions& in, const io::FractionReport& report);

/// The reading options of data's record, if it has one; a record that is not one is an
/// InputError naming `file`.
std::optional<InputOptions> carried_input(const io::MeshData& data, const std::string& file);

/// Copies data's record, if any, into `out`'s metadata.
void pass_input_record(const io::MeshData& data, io::MeshData& out);

/// Whether any flag of add_input_options was given on the command line.
bool input_options_given(const CLI::App& app);

}  // namespace hexadapt::cli
