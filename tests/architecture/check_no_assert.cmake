# cmake -DROOT=<source dir> -P check_no_assert.cmake
# Fails if a source of the product uses assert(), which NDEBUG compiles out of the Release builds
# that CI, campaigns and fuzzing run: invariants use MG_DEMAND (core/demand.h).
cmake_minimum_required(VERSION 3.22)
file(GLOB_RECURSE sources ${ROOT}/src/*.h ${ROOT}/src/*.cpp ${ROOT}/rules/*.h ${ROOT}/rules/*.cpp
                          ${ROOT}/fuzz/*.h ${ROOT}/fuzz/*.cpp ${ROOT}/include/*.h)
set(errors "")
foreach(f ${sources})
  file(STRINGS ${f} lines REGEX "(^|[^_a-zA-Z])assert[ \t]*\\(|#[ \t]*include[ \t]*<(cassert|assert\\.h)>")
  foreach(line ${lines})
    string(STRIP "${line}" line)
    string(APPEND errors "  ${f}: ${line}\n")
  endforeach()
endforeach()
if(errors)
  message(FATAL_ERROR "assert() is compiled out of Release builds; use MG_DEMAND (core/demand.h):\n${errors}")
endif()
