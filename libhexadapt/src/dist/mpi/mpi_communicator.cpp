#include "hexadapt/dist/mpi_communicator.h"

#include <mpi.h>

#include <limits>
#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt::dist {

namespace {

void check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw IoError(std::string(what) + ": " + std::string(text, static_cast<std::size_t>(length)));
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  // Errors come back as codes, which check() turns into exceptions.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

MpiCommunicator::MpiCommunicator() {
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
}

std::vector<std::vector<std::uint8_t>> MpiCommunicator::all_gather(
    const std::vector<std::uint8_t>& mine) const {
  const auto n = static_cast<std::size_t>(size_);
  std::uint64_t count = mine.size();
  std::vector<std::uint64_t> counts(n);
  check(MPI_Allgather(&count, 1, MPI_UINT64_T, counts.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD),
        "MPI_Allgather");
  std::vector<int> sizes(n), offsets(n);
  std::uint64_t total = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (total + counts[r] > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      throw InternalError("a gather of " + std::to_string(total + counts[r]) +
                          " bytes exceeds what one MPI call carries");
    offsets[r] = static_cast<int>(total);
    sizes[r] = static_cast<int>(counts[r]);
    total += counts[r];
  }
  std::vector<std::uint8_t> all(total);
  check(MPI_Allgatherv(mine.data(), static_cast<int>(count), MPI_BYTE, all.data(), sizes.data(),
                       offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
        "MPI_Allgatherv");
  sent_ += sizeof count + count;
  std::vector<std::vector<std::uint8_t>> out(n);
  for (std::size_t r = 0; r < n; ++r)
    out[r].assign(all.begin() + offsets[r], all.begin() + offsets[r] + sizes[r]);
  return out;
}

}  // namespace hexadapt::dist
