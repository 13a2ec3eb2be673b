// A stage's grid and its output on the ranks of an MPI job: each rank reads its slab of a
// structured grid (dist/block.h) with ghost layers, and writes the cells it owns as one
// piece of a .pvtu, or sends them to rank 0, which writes one file of the whole grid.
#pragma once

#include <string>

#include "cli.h"
#include "hexadapt/dist/block.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::cli {

/// What one rank reads of the input grid.
struct RankInput {
  io::StructuredShape shape;  ///< the whole grid's
  dist::Slab slab;            ///< the part this rank holds, and owns
  io::MeshData data;          ///< the held layers
};

/// Every rank's slab of the structured grid in `path`, holding `ghost_layers` layers of
/// cells beyond the ones it owns. A parallel file's pieces outside a slab are not read by its
/// rank; a single file is read whole by every rank, then cut. Errors are common to every
/// rank (on_every_rank).
RankInput read_on_ranks(const dist::Communicator& comm, const CLI::App& app,
                        const std::string& path, io::ReadOptions options, int ghost_layers);

/// Writes the owned part of every rank's `held` data (the layers of `input.slab`) to `path`:
/// a .pvtu naming one .vtu piece per rank (`<path without .pvtu>_<rank>.vtu`, written by
/// their ranks), or with `gather` one file of the whole grid in any format, written by
/// rank 0 with the same bytes a run on one process writes. Errors are common to every rank.
void write_on_ranks(const dist::Communicator& comm, const CLI::App& app, io::MeshData held,
                    const RankInput& input, const std::string& path, bool gather,
                    const io::WriteOptions& options);

/// Throws OptionError when `path` cannot take what write_on_ranks writes (a .pvtu, unless
/// `gather`); `flag` names the option that gave it.
void check_rank_output(const std::string& flag, const std::string& path, bool gather);

}  // namespace hexadapt::cli
