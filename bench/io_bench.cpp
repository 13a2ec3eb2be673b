// Times the VTK XML reader and writers: reads each file given (e.g. the 200^3 .vti files of
// bench/io_bench.py), then writes it as .vtu and .vts, zlib-compressed and raw. Prints
// seconds, file sizes and MB/s (of the file, and of the array data decoded or encoded).
//
//   hexadapt_io_bench [--threads N] [--read-only] FILE.vti...
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/io/vtk_xml.h"

namespace {

// Wall-clock seconds of f; the process CPU seconds (all threads) are added to *cpu, since
// on a shared machine they tell more than the wall clock.
double seconds(const std::function<void()>& f, double* cpu = nullptr) {
  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  f();
  if (cpu) *cpu += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double mb(std::uintmax_t bytes) {
  return static_cast<double>(bytes) / 1e6;
}

std::size_t array_bytes(const hexadapt::io::MeshData& d) {
  std::size_t n = 0;
  for (const auto* group : {&d.cell_data, &d.point_data})
    for (const auto& a : *group) n += a.values.size() * sizeof(double);
  return n;
}

void bench_file(const std::string& path, bool write) {
  std::string content;
  double cpu = 0;
  const double t_load = seconds(
      [&] {
        std::ifstream in(path, std::ios::binary);
        content.resize(std::filesystem::file_size(path));
        in.read(content.data(), static_cast<std::streamsize>(content.size()));
      },
      &cpu);
  hexadapt::io::MeshData data;
  const double t_parse = seconds([&] { data = hexadapt::io::read_vtk_xml(content, path); }, &cpu);
  const std::size_t payload = array_bytes(data);
  std::printf("%s: %.1f MB file, %d cells, %zu arrays (%.1f MB of values)\n", path.c_str(),
              mb(content.size()), data.n_cells(), data.cell_data.size() + data.point_data.size(),
              mb(payload));
  std::printf(
      "  read   %.3f s (load %.3f + decode %.3f; cpu %.3f s): %.0f MB/s of file, "
      "%.0f MB/s of values\n",
      t_load + t_parse, t_load, t_parse, cpu, mb(content.size()) / (t_load + t_parse),
      mb(payload) / (t_load + t_parse));
  content.clear();
  content.shrink_to_fit();
  if (!write) return;
  for (const char* ext : {".vts", ".vtu"})
    for (bool compress : {true, false}) {
      const std::string out = path + (compress ? ".zlib" : ".raw") + ext;
      hexadapt::io::WriteOptions o;
      o.compress = compress;
      double cpu_write = 0;
      const double t = seconds(
          [&] {
            if (std::strcmp(ext, ".vts") == 0)
              hexadapt::io::write_vts(data, out, o);
            else
              hexadapt::io::write_vtu(data, out, o);
          },
          &cpu_write);
      const auto size = std::filesystem::file_size(out);
      std::printf(
          "  write %s %-4s %.3f s (cpu %.3f s): %.1f MB file, %.0f MB/s of file, "
          "%.0f MB/s of values\n",
          ext, compress ? "zlib" : "raw", t, cpu_write, mb(size), mb(size) / t, mb(payload) / t);
      std::filesystem::remove(out);
    }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    bool write = true;
    std::vector<std::string> files;
    for (int k = 1; k < argc; ++k) {
      if (std::strcmp(argv[k], "--threads") == 0 && k + 1 < argc)
        hexadapt::set_threads(std::atoi(argv[++k]));
      else if (std::strcmp(argv[k], "--read-only") == 0)
        write = false;
      else
        files.emplace_back(argv[k]);
    }
    std::printf("threads: %d\n", hexadapt::n_threads());
    for (const std::string& f : files) bench_file(f, write);
    return 0;
  } catch (const hexadapt::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
