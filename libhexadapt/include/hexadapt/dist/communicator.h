// The ranks a computation is spread over, as the stages see them: a rank number, a count, the
// gather of every rank's bytes (on every rank or on one), and the exchange of bytes between
// neighbouring ranks. The stages are written against this interface only;
// SerialCommunicator is the one-rank case every serial call uses, and MpiCommunicator
// (dist/mpi_communicator.h, in the separate hexadapt::mpi library) spreads them over MPI
// processes.
//
// Collectives are called by every rank in the same order. Results are ordered by rank, so a
// computation that combines them in that order gives the same bits on every rank.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "hexadapt/core/exact_sum.h"
#include "hexadapt/core/geometry.h"

namespace hexadapt::dist {

struct DistGraph;

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Every rank's `mine`, indexed by rank, on every rank.
  virtual std::vector<std::vector<std::uint8_t>> all_gather(
      const std::vector<std::uint8_t>& mine) const = 0;
  /// On rank `root`, every rank's `mine`, indexed by rank; on the others, nothing.
  virtual std::vector<std::vector<std::uint8_t>> gather(const std::vector<std::uint8_t>& mine,
                                                        int root) const = 0;
  /// Sends to[i] to rank peers[i] and returns what each peers[i] sent to this rank, in the
  /// same order. Rank r lists s exactly when s lists r; no rank lists itself or one rank twice.
  /// Only the ranks that list each other wait for each other.
  virtual std::vector<std::vector<std::uint8_t>> exchange(
      const std::vector<int>& peers, const std::vector<std::vector<std::uint8_t>>& to) const = 0;
  /// The part (0 .. size() - 1) of each of this rank's vertices of `graph`, a graph spread
  /// over the ranks (dist/dual_graph.h): few edges between parts, the parts balanced.
  /// Deterministic for a given graph and rank count. Every rank calls it.
  virtual std::vector<int> parts_of(const DistGraph& graph) const = 0;
  /// Bytes this rank has sent so far.
  virtual std::uint64_t bytes_sent() const = 0;
  /// Ends every rank of the job with exit code `code`: what a rank does when it fails where
  /// the others cannot know it (they would wait for it in the next collective).
  [[noreturn]] virtual void abort(int code) const = 0;
};

/// One rank: the gather returns `mine`.
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::vector<std::uint8_t>> all_gather(
      const std::vector<std::uint8_t>& mine) const override {
    return {mine};
  }
  std::vector<std::vector<std::uint8_t>> gather(const std::vector<std::uint8_t>& mine,
                                                int) const override {
    return {mine};
  }
  /// One rank has no peer: throws InternalError when given one.
  std::vector<std::vector<std::uint8_t>> exchange(
      const std::vector<int>& peers,
      const std::vector<std::vector<std::uint8_t>>& to) const override;
  /// Every vertex in part 0.
  std::vector<int> parts_of(const DistGraph& graph) const override;
  std::uint64_t bytes_sent() const override { return 0; }
  [[noreturn]] void abort(int code) const override;
};

/// A shared one-rank communicator.
const Communicator& serial();

/// Plain values written one after another into bytes, and read back in the same order.
class Buffer {
 public:
  Buffer() = default;
  explicit Buffer(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}

  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &v, sizeof(T));
  }
  template <class T>
  void put_vector(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    put_values(v.data(), v.size());
  }

  /// n values from `first` in one copy (read back by get_values, into n values).
  template <class T>
  void put_values(const T* first, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto at = bytes_.size();
    bytes_.resize(at + n * sizeof(T));
    if (n > 0) std::memcpy(bytes_.data() + at, first, n * sizeof(T));
  }

  /// A point as its three coordinates (read back by get_point).
  void put_point(const Vec3& p) { put_values(p.data(), 3); }
  Vec3 get_point() {
    Vec3 p;
    get_values(p.data(), 3);
    return p;
  }
  bool done() const { return read_ == bytes_.size(); }
  /// Throws InternalError when the bytes run out (a rank sent something else).
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    check(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + read_, sizeof(T));
    read_ += sizeof(T);
    return v;
  }
  template <class T>
  std::vector<T> get_vector() {
    const auto n = get<std::uint64_t>();
    check(n * sizeof(T));
    std::vector<T> v(n);
    get_values(v.data(), n);
    return v;
  }

  template <class T>
  void get_values(T* first, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    check(n * sizeof(T));
    if (n > 0) std::memcpy(first, bytes_.data() + read_, n * sizeof(T));
    read_ += n * sizeof(T);
  }

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  /// The bytes, moved out: the buffer is left empty.
  std::vector<std::uint8_t> take() {
    read_ = 0;
    return std::move(bytes_);
  }

 private:
  void check(std::uint64_t n) const;
  std::vector<std::uint8_t> bytes_;
  std::size_t read_ = 0;
};

/// Every rank's buffer, in rank order.
std::vector<Buffer> all_gather(const Communicator& comm, const Buffer& mine);
/// What each of `peers` sent, in the order of `peers` (Communicator::exchange). `to` is taken
/// by value: pass it moved, and its bytes are sent without a copy.
std::vector<Buffer> exchange(const Communicator& comm, const std::vector<int>& peers,
                             std::vector<Buffer> to);
/// On rank `root`, every rank's buffer in rank order; on the others, none.
std::vector<Buffer> gather(const Communicator& comm, const Buffer& mine, int root);

/// Every rank's values concatenated in rank order.
template <class T>
std::vector<T> all_gather_values(const Communicator& comm, const std::vector<T>& mine) {
  Buffer b;
  b.put_vector(mine);
  std::vector<T> out;
  for (Buffer& r : all_gather(comm, b)) {
    const std::vector<T> part = r.get_vector<T>();
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

/// The exact sum of every rank's accumulator, as a double: the same bits on every rank and
/// for any split of the values over the ranks.
double exact_sum(const Communicator& comm, const ExactSum& mine);

/// The sum of every rank's value, added in rank order (the same bits on every rank).
template <class T>
T sum_in_rank_order(const Communicator& comm, T mine) {
  T sum{};
  for (const T& v : all_gather_values(comm, std::vector<T>{mine})) sum += v;
  return sum;
}

/// True on every rank when `mine` is true on every rank. Every rank calls it.
bool all_true(const Communicator& comm, bool mine);

}  // namespace hexadapt::dist
