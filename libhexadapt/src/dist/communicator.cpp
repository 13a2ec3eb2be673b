#include "hexadapt/dist/communicator.h"

#include <algorithm>
#include <cstdlib>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/dual_graph.h"

namespace hexadapt::dist {

const Communicator& serial() {
  static const SerialCommunicator one;
  return one;
}

void SerialCommunicator::abort(int code) const {
  std::exit(code);
}

std::vector<std::vector<std::uint8_t>> SerialCommunicator::exchange(
    const std::vector<int>& peers, const std::vector<std::vector<std::uint8_t>>& to) const {
  if (!peers.empty() || !to.empty()) throw InternalError("one rank exchanges with a peer");
  return {};
}

std::vector<int> SerialCommunicator::parts_of(const DistGraph& graph) const {
  return std::vector<int>(static_cast<std::size_t>(graph.n_vertices()), 0);
}

void Buffer::check(std::uint64_t n) const {
  if (n > bytes_.size() - read_)
    throw InternalError("a rank's message ends after " + std::to_string(bytes_.size()) +
                        " bytes, " + std::to_string(n) + " more were expected at byte " +
                        std::to_string(read_));
}

std::vector<Buffer> all_gather(const Communicator& comm, const Buffer& mine) {
  std::vector<Buffer> out;
  for (auto& bytes : comm.all_gather(mine.bytes())) out.emplace_back(std::move(bytes));
  return out;
}

double exact_sum(const Communicator& comm, const ExactSum& mine) {
  if (comm.size() == 1) return mine.value();
  Buffer b;
  b.put(mine.canonical());
  b.put(mine.non_finite());
  ExactSum total;
  for (Buffer& r : all_gather(comm, b)) {
    const auto digits = r.get<std::array<std::int64_t, ExactSum::digits>>();
    total.add(ExactSum::from(digits, r.get<double>()));
  }
  return total.value();
}

std::vector<Buffer> exchange(const Communicator& comm, const std::vector<int>& peers,
                             std::vector<Buffer> to) {
  std::vector<std::vector<std::uint8_t>> bytes;
  for (Buffer& b : to) bytes.push_back(b.take());
  to = {};
  std::vector<Buffer> out;
  for (auto& b : comm.exchange(peers, bytes)) out.emplace_back(std::move(b));
  return out;
}

std::vector<Buffer> gather(const Communicator& comm, const Buffer& mine, int root) {
  std::vector<Buffer> out;
  for (auto& bytes : comm.gather(mine.bytes(), root)) out.emplace_back(std::move(bytes));
  return out;
}

bool all_true(const Communicator& comm, bool mine) {
  const std::vector<char> all = all_gather_values(comm, std::vector<char>{mine});
  return std::find(all.begin(), all.end(), 0) == all.end();
}

}  // namespace hexadapt::dist
