// The processes a tool runs on: the ranks of the MPI job that started it (mpirun, srun), or
// this process alone. MPI is started only when a launcher started the process, so a tool run
// by hand never touches it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "hexadapt/dist/communicator.h"
#include "hexadapt/dist/dual_graph.h"

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

/// One part per rank of `comm` for each of this rank's vertices of `graph` (a mesh's dual
/// graph): PT-Scotch's cut (dist/scotch_partition.h) on the ranks of an MPI job, part 0 for
/// everything on one process. Every rank calls it.
std::vector<int> partition_by_rank(const dist::Communicator& comm, const dist::DistGraph& graph);

/// The largest resident memory this process has held so far, in bytes (getrusage).
std::uint64_t peak_resident_bytes();

}  // namespace hexadapt::cli
