// libFuzzer target for the Exodus II reader. The Exodus library (on netCDF) opens files by
// name, so each input is written to an in-memory file (memfd) and read through its
// /proc/self/fd path. The Debian netCDF and Exodus libraries are not instrumented: coverage
// guidance stops at their door, ASan sees their heap use only through its interceptors.
#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "fuzz_reader.h"
#include "hexadapt/io/exodus.h"

namespace {

int memory_file() {
  static const int fd = [] {
    const int f = memfd_create("fuzz_exodus", 0);
    if (f < 0) std::abort();
    return f;
  }();
  return fd;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  return hexadapt::fuzz::init_single_thread();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const int fd = memory_file();
  if (ftruncate(fd, 0) != 0 || pwrite(fd, bytes, size, 0) != static_cast<ssize_t>(size))
    std::abort();
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  return hexadapt::fuzz::run_reader(bytes, size, [&](std::string_view) {
    hexadapt::io::ReadOptions options;
    if (size > 0 && bytes[size - 1] == 1) options.step = 1;  // the step path too
    return hexadapt::io::read_exodus(path, options);
  });
}
