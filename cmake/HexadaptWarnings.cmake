# Warning and sanitizer flags shared by every target of the project.
add_library(hexadapt_warnings INTERFACE)
target_compile_options(hexadapt_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wconversion -Wnull-dereference -Wdouble-promotion
  -Wimplicit-fallthrough)
# OpenMesh's property containers push_back default-constructed (uninitialised) vectors, which
# GCC 12 flags inside our translation units; the warning says nothing about our code.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(hexadapt_warnings INTERFACE -Wno-maybe-uninitialized)
endif()
# Clang's -Wconversion also implies -Wsign-conversion, which GCC leaves out: keep the two
# compilers to the same set (indexing std::vector with signed ids is routine here).
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  target_compile_options(hexadapt_warnings INTERFACE -Wno-sign-conversion)
endif()
if(HEXADAPT_WERROR)
  target_compile_options(hexadapt_warnings INTERFACE -Werror)
endif()
# float-cast-overflow (a double out of an integer's range cast to it) is not part of
# "undefined" in GCC nor clang: named on its own.
if(HEXADAPT_SANITIZE)
  target_compile_options(hexadapt_warnings INTERFACE
    -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  target_link_options(hexadapt_warnings INTERFACE -fsanitize=address,undefined,float-cast-overflow)
endif()
if(HEXADAPT_FUZZ)
  # Coverage instrumentation for libFuzzer in every target (the fuzz executables add
  # -fsanitize=fuzzer, which brings libFuzzer's main), plus the sanitizers that turn silent
  # memory errors into crashes.
  target_compile_options(hexadapt_warnings INTERFACE
    -fsanitize=fuzzer-no-link,address,undefined,float-cast-overflow -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  target_link_options(hexadapt_warnings INTERFACE -fsanitize=address,undefined,float-cast-overflow)
endif()
