// The ranks of an MPI job (MPI_COMM_WORLD) as a dist::Communicator. This header belongs to
// the separate library hexadapt::mpi, built when CMake finds MPI (HEXADAPT_MPI); the rest of
// libhexadapt does not depend on MPI.
#pragma once

#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {

/// Starts MPI on construction (threads funnelled: only the calling thread talks to MPI) and
/// finalizes it on destruction. One per process, made before any MpiCommunicator.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

/// The gathers carry any size: they go in rounds of at most `round_bytes` bytes over all
/// ranks (MPI counts are int), each rank's bytes arriving in order; the exchange sends each
/// peer's bytes in messages of at most `round_bytes`, all of a round posted at once
/// (non-blocking), so no order of the peers can deadlock.
class MpiCommunicator final : public Communicator {
 public:
  static constexpr std::uint64_t default_round_bytes = std::uint64_t(1) << 28;  // 256 MiB

  explicit MpiCommunicator(std::uint64_t round_bytes = default_round_bytes);
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::vector<std::vector<std::uint8_t>> all_gather(
      const std::vector<std::uint8_t>& mine) const override;
  std::vector<std::vector<std::uint8_t>> gather(const std::vector<std::uint8_t>& mine,
                                                int root) const override;
  std::vector<std::vector<std::uint8_t>> exchange(
      const std::vector<int>& peers,
      const std::vector<std::vector<std::uint8_t>>& to) const override;
  /// PT-Scotch's parts (dist/scotch_partition.h), one per rank.
  std::vector<int> parts_of(const DistGraph& graph) const override;
  std::uint64_t bytes_sent() const override { return sent_; }
  [[noreturn]] void abort(int code) const override;

 private:
  std::vector<std::vector<std::uint8_t>> gather_rounds(const std::vector<std::uint8_t>& mine,
                                                       int root) const;  // root < 0: all

  int rank_ = 0, size_ = 1;
  std::uint64_t round_bytes_;
  mutable std::uint64_t sent_ = 0;
};

}  // namespace hexadapt::dist
