#include "material_names.h"

#include "hexadapt/io/assigned_grid_file.h"

namespace hexadapt::io::detail {

std::vector<std::string> material_names(const MeshData& data) {
  // adapt writes `materials`, assign and reconstruct `hexadapt_materials`.
  const std::string* joined = nullptr;
  for (const char* wanted : {"hexadapt_materials", "materials"})
    for (const auto& [key, value] : data.metadata)
      if (key == wanted) joined = &value;
  return joined ? split_material_names(*joined) : std::vector<std::string>{};
}

}  // namespace hexadapt::io::detail
