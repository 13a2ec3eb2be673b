#include "hexadapt/dist/mpi_communicator.h"

#include <mpi.h>

#include <cstdlib>
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

void MpiCommunicator::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return
}

namespace {

/// Displacements of `counts` bytes laid one after another, within what one MPI call carries.
std::vector<int> offsets_of(const std::vector<std::uint64_t>& counts) {
  std::vector<int> offsets(counts.size());
  std::uint64_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    if (total + counts[r] > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      throw InternalError("a gather of " + std::to_string(total + counts[r]) +
                          " bytes exceeds what one MPI call carries");
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  return offsets;
}

std::vector<std::vector<std::uint8_t>> split(const std::vector<std::uint8_t>& all,
                                             const std::vector<std::uint64_t>& counts,
                                             const std::vector<int>& offsets) {
  std::vector<std::vector<std::uint8_t>> out(counts.size());
  for (std::size_t r = 0; r < counts.size(); ++r)
    out[r].assign(all.begin() + offsets[r],
                  all.begin() + offsets[r] + static_cast<std::ptrdiff_t>(counts[r]));
  return out;
}

std::vector<int> as_int(const std::vector<std::uint64_t>& counts) {
  return {counts.begin(), counts.end()};  // offsets_of checked the total
}

}  // namespace

std::vector<std::vector<std::uint8_t>> MpiCommunicator::all_gather(
    const std::vector<std::uint8_t>& mine) const {
  std::uint64_t count = mine.size();
  std::vector<std::uint64_t> counts(static_cast<std::size_t>(size_));
  check(MPI_Allgather(&count, 1, MPI_UINT64_T, counts.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD),
        "MPI_Allgather");
  const std::vector<int> offsets = offsets_of(counts);
  std::vector<std::uint8_t> all(static_cast<std::size_t>(offsets.back()) + counts.back());
  check(MPI_Allgatherv(mine.data(), static_cast<int>(count), MPI_BYTE, all.data(),
                       as_int(counts).data(), offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
        "MPI_Allgatherv");
  sent_ += sizeof count + count;
  return split(all, counts, offsets);
}

std::vector<std::vector<std::uint8_t>> MpiCommunicator::gather(
    const std::vector<std::uint8_t>& mine, int root) const {
  std::uint64_t count = mine.size();
  std::vector<std::uint64_t> counts(static_cast<std::size_t>(size_));
  check(MPI_Gather(&count, 1, MPI_UINT64_T, counts.data(), 1, MPI_UINT64_T, root, MPI_COMM_WORLD),
        "MPI_Gather");
  sent_ += sizeof count + count;
  if (count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    throw InternalError("a gather of " + std::to_string(count) +
                        " bytes exceeds what one MPI call carries");
  if (rank_ != root) {
    check(MPI_Gatherv(mine.data(), static_cast<int>(count), MPI_BYTE, nullptr, nullptr, nullptr,
                      MPI_BYTE, root, MPI_COMM_WORLD),
          "MPI_Gatherv");
    return {};
  }
  const std::vector<int> offsets = offsets_of(counts);
  std::vector<std::uint8_t> all(static_cast<std::size_t>(offsets.back()) + counts.back());
  check(MPI_Gatherv(mine.data(), static_cast<int>(count), MPI_BYTE, all.data(),
                    as_int(counts).data(), offsets.data(), MPI_BYTE, root, MPI_COMM_WORLD),
        "MPI_Gatherv");
  return split(all, counts, offsets);
}

}  // namespace hexadapt::dist
