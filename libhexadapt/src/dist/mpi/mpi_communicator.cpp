#include "hexadapt/dist/mpi_communicator.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
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

MpiCommunicator::MpiCommunicator(std::uint64_t round_bytes) : round_bytes_(round_bytes) {
  if (round_bytes_ == 0 || round_bytes_ > static_cast<std::uint64_t>(INT_MAX))
    throw InternalError("MPI gather rounds of " + std::to_string(round_bytes_) + " bytes");
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
}

void MpiCommunicator::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return
}

std::vector<std::vector<std::uint8_t>> MpiCommunicator::all_gather(
    const std::vector<std::uint8_t>& mine) const {
  return gather_rounds(mine, -1);
}

std::vector<std::vector<std::uint8_t>> MpiCommunicator::gather(
    const std::vector<std::uint8_t>& mine, int root) const {
  return gather_rounds(mine, root);
}

// Every rank learns every rank's byte count; then each round carries up to `share` bytes of
// each rank's buffer (share x ranks <= round_bytes), until the largest buffer is through.
std::vector<std::vector<std::uint8_t>> MpiCommunicator::gather_rounds(
    const std::vector<std::uint8_t>& mine, int root) const {
  std::uint64_t count = mine.size();
  std::vector<std::uint64_t> counts(static_cast<std::size_t>(size_));
  check(MPI_Allgather(&count, 1, MPI_UINT64_T, counts.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD),
        "MPI_Allgather");
  sent_ += sizeof count + count;
  const bool receives = root < 0 || rank_ == root;
  std::vector<std::vector<std::uint8_t>> out(receives ? counts.size() : 0);
  for (std::size_t r = 0; r < out.size(); ++r) out[r].reserve(counts[r]);
  const std::uint64_t share = std::max<std::uint64_t>(1, round_bytes_ / counts.size());
  const std::uint64_t largest = *std::max_element(counts.begin(), counts.end());
  std::vector<int> part(counts.size()), offsets(counts.size());
  std::vector<std::uint8_t> round;
  for (std::uint64_t done = 0; done < largest; done += share) {
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
      part[r] = static_cast<int>(counts[r] > done ? std::min(share, counts[r] - done) : 0);
      offsets[r] = total;
      total += part[r];
    }
    round.resize(receives ? static_cast<std::size_t>(total) : 0);
    const auto me = static_cast<std::size_t>(rank_);
    const std::uint8_t* from = part[me] > 0 ? mine.data() + done : mine.data();
    if (root < 0)
      check(MPI_Allgatherv(from, part[me], MPI_BYTE, round.data(), part.data(), offsets.data(),
                           MPI_BYTE, MPI_COMM_WORLD),
            "MPI_Allgatherv");
    else
      check(MPI_Gatherv(from, part[me], MPI_BYTE, round.data(), part.data(), offsets.data(),
                        MPI_BYTE, root, MPI_COMM_WORLD),
            "MPI_Gatherv");
    for (std::size_t r = 0; r < out.size(); ++r)
      out[r].insert(out[r].end(), round.begin() + offsets[r], round.begin() + offsets[r] + part[r]);
  }
  return out;
}

std::vector<std::vector<std::uint8_t>> MpiCommunicator::exchange(
    const std::vector<int>& peers, const std::vector<std::vector<std::uint8_t>>& to) const {
  if (to.size() != peers.size()) throw InternalError("exchange: one buffer per peer");
  const std::size_t n = peers.size();
  std::vector<std::uint64_t> counts(n), sizes(n);
  std::vector<MPI_Request> requests;
  requests.reserve(2 * n);
  const auto wait = [&] {
    check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
          "MPI_Waitall");
    requests.clear();
  };
  for (std::size_t i = 0; i < n; ++i) {
    sizes[i] = to[i].size();
    requests.emplace_back();
    check(MPI_Irecv(&counts[i], 1, MPI_UINT64_T, peers[i], 1, MPI_COMM_WORLD, &requests.back()),
          "MPI_Irecv");
    requests.emplace_back();
    check(MPI_Isend(&sizes[i], 1, MPI_UINT64_T, peers[i], 1, MPI_COMM_WORLD, &requests.back()),
          "MPI_Isend");
  }
  wait();
  std::vector<std::vector<std::uint8_t>> out(n);
  std::uint64_t largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    out[i].resize(counts[i]);
    largest = std::max({largest, counts[i], sizes[i]});
    sent_ += sizeof(std::uint64_t) + sizes[i];
  }
  // Message k to or from a peer carries bytes [k R, (k + 1) R); messages between two ranks
  // with one tag arrive in the order they were sent.
  for (std::uint64_t done = 0; done < largest; done += round_bytes_) {
    for (std::size_t i = 0; i < n; ++i) {
      if (counts[i] > done) {
        requests.emplace_back();
        check(MPI_Irecv(out[i].data() + done,
                        static_cast<int>(std::min(round_bytes_, counts[i] - done)), MPI_BYTE,
                        peers[i], 2, MPI_COMM_WORLD, &requests.back()),
              "MPI_Irecv");
      }
      if (sizes[i] > done) {
        requests.emplace_back();
        check(MPI_Isend(to[i].data() + done,
                        static_cast<int>(std::min(round_bytes_, sizes[i] - done)), MPI_BYTE,
                        peers[i], 2, MPI_COMM_WORLD, &requests.back()),
              "MPI_Isend");
      }
    }
    wait();
  }
  return out;
}

}  // namespace hexadapt::dist
