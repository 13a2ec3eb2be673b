#include "hexadapt/io/material_names.h"

#include <algorithm>
#include <sstream>

namespace hexadapt::io {
namespace {

const std::string* last_entry(const MeshData& data, const std::string& key) {
  const std::string* value = nullptr;
  for (const auto& [k, v] : data.metadata)
    if (k == key) value = &v;
  return value;
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string line; std::getline(in, line, '\n');) out.push_back(line);
  return out;
}

}  // namespace

std::string join_material_names(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ',';
    for (char ch : names[i]) {
      if (ch == ',' || ch == '\\') out += '\\';
      out += ch;
    }
  }
  return out;
}

std::vector<std::string> split_material_names(const std::string& joined) {
  std::vector<std::string> out;
  if (joined.empty()) return out;
  out.emplace_back();
  for (std::size_t i = 0; i < joined.size(); ++i) {
    if (joined[i] == '\\' && i + 1 < joined.size())
      out.back() += joined[++i];
    else if (joined[i] == ',')
      out.emplace_back();
    else
      out.back() += joined[i];
  }
  return out;
}

void set_material_names(MeshData& data, const std::vector<std::string>& names) {
  auto& meta = data.metadata;
  meta.erase(std::remove_if(meta.begin(), meta.end(),
                            [](const auto& kv) { return kv.first == material_names_key; }),
             meta.end());
  meta.emplace_back(material_names_key, join_material_names(names));
}

std::vector<std::string> material_names(const MeshData& data) {
  for (const char* key : {material_names_key, "materials"})
    if (const std::string* joined = last_entry(data, key); joined && !joined->empty())
      return split_material_names(*joined);
  if (const std::string* field = last_entry(data, "material_names")) return lines(*field);
  return {};
}

}  // namespace hexadapt::io
