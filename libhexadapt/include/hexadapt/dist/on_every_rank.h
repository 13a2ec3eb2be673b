// Errors every rank of a distributed stage agrees on. A stage spread over the ranks runs
// collective steps (gathers, exchanges) between pieces of work that may throw on some ranks
// only (a bad cell in one rank's part); a rank that stopped alone would leave the others
// waiting in the next collective step forever. Each such piece runs inside on_every_rank: when
// it throws on some ranks, every rank throws the same error, the lowest such rank's.
#pragma once

#include <exception>
#include <functional>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/communicator.h"

namespace hexadapt::dist {

/// The error a piece of work threw on some rank, thrown on every rank: `original()` rebuilds
/// that rank's exception with its type (InputError with its file, place and message,
/// OptionError, std::bad_alloc, ...; an exception of another type as InternalError with its
/// message), for the caller to report as it reports that type.
class CommonError : public Error {
 public:
  CommonError(int rank, std::exception_ptr original);
  int rank() const { return rank_; }  ///< the lowest rank that threw
  const std::exception_ptr& original() const { return original_; }

 private:
  int rank_;
  std::exception_ptr original_;
};

/// Runs `f` on every rank (collectively: every rank calls it); when it throws on some, every
/// rank throws the CommonError of the lowest such rank. On one rank, f's exception passes
/// unchanged; a CommonError thrown inside `f` (already common) passes unchanged too.
void on_every_rank(const Communicator& comm, const std::function<void()>& f);

}  // namespace hexadapt::dist
