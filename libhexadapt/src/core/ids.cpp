#include "hexadapt/core/ids.h"

#include <string>

#include "hexadapt/core/error.h"

namespace hexadapt {

index_t checked_index(std::size_t n, const char* what) {
  if (n > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
    throw Error(std::string("too many ") + what + " (" + std::to_string(n) +
                "): ids are 32-bit");
  return static_cast<index_t>(n);
}

}  // namespace hexadapt
