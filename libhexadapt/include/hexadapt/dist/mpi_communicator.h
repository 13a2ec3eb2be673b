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

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator();
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::vector<std::vector<std::uint8_t>> all_gather(
      const std::vector<std::uint8_t>& mine) const override;
  std::vector<std::vector<std::uint8_t>> gather(const std::vector<std::uint8_t>& mine,
                                                int root) const override;
  std::uint64_t bytes_sent() const override { return sent_; }
  [[noreturn]] void abort(int code) const override;

 private:
  int rank_ = 0, size_ = 1;
  mutable std::uint64_t sent_ = 0;
};

}  // namespace hexadapt::dist
