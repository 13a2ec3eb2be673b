#include "ranks.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "hexadapt/core/error.h"
#ifdef HEXADAPT_TOOLS_MPI
#include "hexadapt/dist/mpi_communicator.h"
#include "hexadapt/dist/scotch_partition.h"
#endif

namespace hexadapt::cli {

int launched_ranks() {
  // OpenMPI's mpirun, then the PMI variable of Slurm's srun and of MPICH's launcher.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return 1;
}

std::vector<int> partition_by_rank(const dist::Communicator& comm, const dist::DistGraph& graph) {
#ifdef HEXADAPT_TOOLS_MPI
  if (const auto* mpi = dynamic_cast<const dist::MpiCommunicator*>(&comm))
    return dist::scotch_partition(*mpi, graph, comm.size());
#endif
  if (comm.size() > 1) throw InternalError("ranks that are not an MPI job's");
  return std::vector<int>(static_cast<std::size_t>(graph.n_vertices()), 0);
}

std::uint64_t peak_resident_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<std::uint64_t>(u.ru_maxrss) * 1024;  // Linux counts kibibytes
}

#ifdef HEXADAPT_TOOLS_MPI
struct Ranks::Mpi {
  Mpi(int& argc, char**& argv) : session(argc, argv) {}
  dist::MpiSession session;
  dist::MpiCommunicator comm;
};

Ranks::Ranks(int& argc, char**& argv) {
  if (launched_ranks() > 1) mpi_ = std::make_unique<Mpi>(argc, argv);
}
#else
struct Ranks::Mpi {};

Ranks::Ranks(int&, char**&) {
  if (launched_ranks() > 1)
    throw OptionError("started as " + std::to_string(launched_ranks()) +
                      " processes, but this build has no MPI (configure with HEXADAPT_MPI=ON)");
}
#endif

Ranks::~Ranks() = default;

const dist::Communicator& Ranks::comm() const {
#ifdef HEXADAPT_TOOLS_MPI
  if (mpi_) return mpi_->comm;
#endif
  return dist::serial();
}

}  // namespace hexadapt::cli
