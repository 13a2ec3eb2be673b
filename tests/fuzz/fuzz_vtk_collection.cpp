// libFuzzer target for the collection reader (.pvtu .pvts .pvtr .pvti .vtm .pvd). One input
// holds the collection file and the files it names, served from memory:
//   <collection file>
//   --8<-- NAME
//   <the file NAME>
//   --8<-- NAME2
//   ...
// A name the input does not hold is a missing file (IoError), as on disk.
#include <map>
#include <string>

#include "fuzz_reader.h"
#include "hexadapt/io/vtk_collection.h"

namespace {

constexpr std::string_view separator = "\n--8<-- ";

std::map<std::string, std::string> split_files(std::string_view content, std::string_view& main) {
  std::map<std::string, std::string> files;
  std::size_t at = content.find(separator);
  main = content.substr(0, at);
  while (at != std::string_view::npos) {
    const std::size_t name_at = at + separator.size();
    const std::size_t line_end = content.find('\n', name_at);
    const std::string name(content.substr(
        name_at, line_end == std::string_view::npos ? std::string_view::npos : line_end - name_at));
    at = line_end == std::string_view::npos ? line_end : content.find(separator, line_end);
    if (line_end != std::string_view::npos)
      files.emplace(name, std::string(content.substr(line_end + 1, at == std::string_view::npos
                                                                       ? std::string_view::npos
                                                                       : at - line_end - 1)));
  }
  return files;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  return hexadapt::fuzz::init_single_thread();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  return hexadapt::fuzz::run_reader(bytes, size, [](std::string_view content) {
    std::string_view main;
    const std::map<std::string, std::string> files = split_files(content, main);
    const hexadapt::io::FileLoader load = [&files](const std::string& path) {
      const auto it = files.find(path);
      if (it == files.end()) throw hexadapt::IoError(path + ": cannot open: no such file");
      return it->second;
    };
    hexadapt::io::ReadOptions options;
    options.step = 0;
    return hexadapt::io::read_vtk_collection(main, "fuzz", options, load);
  });
}
