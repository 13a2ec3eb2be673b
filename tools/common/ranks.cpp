#include "ranks.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/on_every_rank.h"
#ifdef HEXADAPT_TOOLS_MPI
#include "hexadapt/dist/mpi_communicator.h"
#endif

namespace hexadapt::cli {

int launched_ranks() {
  // OpenMPI's mpirun, then the PMI variable of Slurm's srun and of MPICH's launcher.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return 1;
}

std::uint64_t peak_resident_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<std::uint64_t>(u.ru_maxrss) * 1024;  // Linux counts kibibytes
}

std::vector<std::int64_t> grid_labels(const dist::Communicator& comm, const InputOptions& input,
                                      const std::string& path, const io::RankInput& in) {
  std::vector<std::int64_t> mine;
  dist::on_every_rank(
      comm, [&] { mine = io::label_values(in.data, input.fractions, path, &in.slab.block); });
  std::vector<std::int64_t> all = dist::all_gather_values(comm, mine);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

Json ranks_json(const dist::Communicator& comm, const io::RankInput& in) {
  Json j = {{"count", comm.size()}};
  if (in.structured) {
    const dist::Slab& slab = in.slab;
    const std::vector<int> owned(slab.owned_layers.begin(), slab.owned_layers.end());
    const std::vector<int> all = dist::all_gather_values(comm, owned);
    Json layers = Json::array();
    for (std::size_t r = 0; r + 1 < all.size(); r += 2) layers.push_back({all[r], all[r + 1]});
    j["layers"] = layers;
  } else {
    const dist::Block& b = in.slab.block;
    j["cells"] = dist::all_gather_values(comm, std::vector<std::int64_t>{b.owned_cell_end});
    j["ghost_cells"] =
        dist::all_gather_values(comm, std::vector<std::int64_t>{b.held_cells - b.owned_cell_end});
  }
  j["bytes_sent"] = dist::all_gather_values(comm, std::vector<std::uint64_t>{comm.bytes_sent()});
  j["peak_memory"] =
      dist::all_gather_values(comm, std::vector<std::uint64_t>{peak_resident_bytes()});
  return j;
}

void check_rank_output(const std::string& flag, const std::string& path, bool gather,
                       bool structured) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (gather || path.empty() || extension == ".pvtu" || (structured && extension == ".pvts"))
    return;
  const std::string formats =
      structured ? "a .pvtu (.vtu pieces) or a .pvts (.vts pieces)" : "a .pvtu (.vtu pieces)";
  throw OptionError(flag + " " + path +
                    ": on several ranks the output is one piece per rank and the parallel file "
                    "that names them: give " +
                    formats + ", or --gather for one file of the whole " +
                    (structured ? "grid" : "mesh"));
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
