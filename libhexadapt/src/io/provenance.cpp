#include "provenance.h"

namespace hexadapt::io::detail {

const std::string* last_command(const MeshData& data) {
  const std::string* found = nullptr;
  for (const auto& [key, value] : data.metadata)
    if (key == command_key) found = &value;
  return found;
}

}  // namespace hexadapt::io::detail
