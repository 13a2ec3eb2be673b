// libFuzzer target for the VTK XML reader (.vtu .vti .vtr .vts, every encoding).
#include "fuzz_reader.h"
#include "hexadapt/io/vtk_xml.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  return hexadapt::fuzz::init_single_thread();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  return hexadapt::fuzz::run_reader(bytes, size, [](std::string_view content) {
    return hexadapt::io::read_vtk_xml(content, "fuzz.vtu");
  });
}
