// The processes a tool runs on: the ranks of the MPI job that started it (mpirun, srun), or
// this process alone. MPI is started only when a launcher started the process, so a tool run
// by hand never touches it.
// Beside them, what the tools add to the library's per-rank files (io/rank_files.h): the
// labels of a label map over the whole grid, the report's `ranks` block, the check that an
// output path can take one piece per rank.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cli.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/io/rank_files.h"

namespace hexadapt::cli {

class Ranks {
 public:
  /// Starts MPI when the tools were built with it and an MPI launcher started this process.
  /// Throws OptionError when a launcher started several processes of tools built without
  /// MPI (each would write the same files).
  Ranks(int& argc, char**& argv);
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  const dist::Communicator& comm() const;

 private:
  struct Mpi;
  std::unique_ptr<Mpi> mpi_;
};

/// The number of processes the MPI launcher that started this one says the job has; 1 when
/// no launcher did.
int launched_ranks();

/// The largest resident memory this process has held so far, in bytes (getrusage).
std::uint64_t peak_resident_bytes();

/// The labels of the label map `input` reads (--labels), over the whole grid: every rank's,
/// merged, increasing. Errors are common to every rank.
std::vector<std::int64_t> grid_labels(const dist::Communicator& comm, const InputOptions& input,
                                      const std::string& path, const io::RankInput& in);

/// The report's `ranks` block: the rank count, and per rank the layers of `in.slab` it owns
/// (of an unstructured mesh: the cells it owns and its ghost cells), the bytes sent and the
/// peak resident memory. Every rank calls it.
Json ranks_json(const dist::Communicator& comm, const io::RankInput& in);

/// Throws OptionError when `path` cannot take what io::write_on_ranks writes (a .pvtu, or a .pvts
/// when `structured`, unless `gather`); `flag` names the option that gave it.
void check_rank_output(const std::string& flag, const std::string& path, bool gather,
                       bool structured = true);

}  // namespace hexadapt::cli
