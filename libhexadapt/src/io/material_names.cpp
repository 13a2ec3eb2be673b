#include "material_names.h"

namespace hexadapt::io::detail {

std::vector<std::string> material_names(const MeshData& data) {
  // adapt writes `materials`, assign and reconstruct `hexadapt_materials`.
  const std::string* joined = nullptr;
  for (const char* wanted : {"hexadapt_materials", "materials"})
    for (const auto& [key, value] : data.metadata)
      if (key == wanted) joined = &value;
  std::vector<std::string> out;
  if (joined == nullptr || joined->empty()) return out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = joined->find(',', start);
    out.push_back(
        joined->substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

}  // namespace hexadapt::io::detail
