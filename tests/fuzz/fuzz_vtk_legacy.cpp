// libFuzzer target for the legacy VTK reader (.vtk, ASCII and binary).
#include "fuzz_reader.h"
#include "hexadapt/io/vtk_legacy.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  return hexadapt::fuzz::init_single_thread();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  return hexadapt::fuzz::run_reader(bytes, size, [](std::string_view content) {
    return hexadapt::io::read_vtk_legacy(content, "fuzz.vtk");
  });
}
