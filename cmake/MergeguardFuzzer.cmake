# Coverage-guided fuzz targets (docs/fuzzing.md "Coverage-guided fuzzing"), one per input type,
# each next to the code it feeds: mg_fuzzer(<name> LINK <deps...>) builds <name>.cpp of the
# calling directory into the executable <name> at the top of the build tree, where build.sh and
# the test command pick it up. mg_module leaves *_fuzzer.cpp out of the libraries.
#
# Built only when the compiler supports -fsanitize=fuzzer (clang; GCC does not). Configure with
# CXX=clang++ to get them; add -DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link,address,undefined so
# that everything is instrumented, or -DMG_FUZZ_INSTRUMENT=ON for the module libraries and the
# fuzz targets only. MG_FUZZ_ENGINE names the engine to link instead (ClusterFuzzLite/OSS-Fuzz
# pass $LIB_FUZZING_ENGINE: -fsanitize=fuzzer, or an engine library such as AFL++'s; docs/fleet.md).
set(MG_FUZZ_ENGINE "" CACHE STRING "Fuzzing engine to link the fuzz targets with (e.g. -fsanitize=fuzzer)")
if(MG_FUZZ_ENGINE)
  set(MG_HAVE_LIBFUZZER ON)
  set(mg_fuzz_engine ${MG_FUZZ_ENGINE})
else()
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer")
  check_cxx_source_compiles([=[
#include <cstddef>
#include <cstdint>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]=] MG_HAVE_LIBFUZZER)
  unset(CMAKE_REQUIRED_FLAGS)
  set(mg_fuzz_engine -fsanitize=fuzzer)
endif()

function(mg_fuzzer name)
  if(NOT MG_HAVE_LIBFUZZER)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "LINK" ${ARGN})
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp)
  if(NOT MG_FUZZ_ENGINE)
    target_compile_options(${name} PRIVATE -fsanitize=fuzzer)
  elseif(MG_FUZZ_INSTRUMENT)
    target_compile_options(${name} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
  target_link_libraries(${name} PRIVATE ${ARG_LINK} ${mg_fuzz_engine})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR})
endfunction()
