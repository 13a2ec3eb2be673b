#include "hexadapt/dist/communicator.h"

#include "hexadapt/core/error.h"

namespace hexadapt::dist {

const Communicator& serial() {
  static const SerialCommunicator one;
  return one;
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

}  // namespace hexadapt::dist
