// libFuzzer target for the plain text case reader (DESIGN sec. 7.1).
#include "fuzz_reader.h"
#include "hexadapt/io/text_case.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  return hexadapt::fuzz::init_single_thread();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  return hexadapt::fuzz::run_reader(bytes, size, [](std::string_view content) {
    return hexadapt::io::read_text_case(content, "fuzz.txt");
  });
}
