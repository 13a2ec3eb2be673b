// The body shared by the reader fuzz targets (libFuzzer, clang): parse the bytes, then build
// the mesh kernel from what was read. A typed hexadapt::Error is the expected answer to bad
// input; any other exception, a crash, a sanitizer report, a leak or a hang is a bug.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>
#include <typeinfo>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/io/mesh_data.h"

namespace hexadapt::fuzz {

/// Above this many cells the kernel is not built: a few bytes may describe a large grid
/// truthfully (a 1001 x 1001 STRUCTURED_POINTS needs no coordinates), and building its mesh
/// under ASan passes the fuzzer's memory limit without any lie in the file.
constexpr index_t max_kernel_cells = 100'000;

/// Runs read(content) and to_mesh on its result (up to max_kernel_cells); aborts (a libFuzzer
/// crash) on any exception that is not a hexadapt::Error.
template <class Read>
int run_reader(const std::uint8_t* bytes, std::size_t size, Read read) {
  const std::string_view content(reinterpret_cast<const char*>(bytes), size);
  try {
    const io::MeshData data = read(content);
    if (data.dim != 0 && data.n_cells() <= max_kernel_cells) (void)io::to_mesh(data);
  } catch (const Error&) {
    // Bad input reported the way the library promises.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: unexpected exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
  return 0;
}

/// One thread: the readers' results must not depend on it, and a single thread keeps the
/// fuzzer's runs reproducible and cheap.
inline int init_single_thread() {
  set_threads(1);
  return 0;
}

}  // namespace hexadapt::fuzz
