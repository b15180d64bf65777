include(GNUInstallDirs)

# mg_module(<target> LINK <deps...>): a static library from every .cpp in the calling
# directory (but main.cpp, an executable's, and *_fuzzer.cpp); headers are included as
# "<module dir>/<file>.h" relative to src/ or the top level, in the build tree and, installed, under
# include/mergeguard/ (docs/package.md). The library is exported as mergeguard::<module dir>
# (mg_rules as mergeguard::rules) and named libmergeguard_<module dir>.a.
function(mg_module target)
  cmake_parse_arguments(ARG "" "" "LINK" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX ".*_fuzzer\\.cpp$")
  list(FILTER sources EXCLUDE REGEX "/main\\.cpp$")
  file(RELATIVE_PATH module_dir ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  string(REGEX REPLACE "^src/" "" module_dir "${module_dir}")
  set(include_dirs $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src> $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                   $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mergeguard>)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC ${include_dirs})
    target_link_libraries(${target} PUBLIC ${ARG_LINK})
    # The headers use C++20: a requirement consumers inherit (a feature, not a forced flag).
    target_compile_features(${target} PUBLIC cxx_std_20)
    if(MG_FUZZ_INSTRUMENT)
      target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
    set_target_properties(${target} PROPERTIES OUTPUT_NAME mergeguard_${module_dir})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${include_dirs})
    target_link_libraries(${target} INTERFACE ${ARG_LINK})
    target_compile_features(${target} INTERFACE cxx_std_20)
  endif()
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${module_dir})
  add_library(mergeguard::${module_dir} ALIAS ${target})
  install(TARGETS ${target} EXPORT mergeguardTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB headers CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.h)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mergeguard/${module_dir})
endfunction()

# mg_test(<name> LINK <deps...>): one GoogleTest executable from every *_test.cpp in the
# calling directory, registered with CTest test by test.
function(mg_test name)
  cmake_parse_arguments(ARG "" "" "LINK" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name} ${sources})
  target_link_libraries(${name} PRIVATE ${ARG_LINK} rapidcheck GTest::gtest GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR})
  target_compile_definitions(${name} PRIVATE
    MG_SOURCE_DIR="${PROJECT_SOURCE_DIR}" MG_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(MG_PCH)
    # Parsed once per test executable instead of once per test file: CI builds the suite twice.
    target_precompile_headers(${name} PRIVATE <gtest/gtest.h> <rapidcheck.h> <rapidcheck/gtest.h>
                              <nlohmann/json.hpp> <string> <vector>)
    # GCC 12 then inlines std::string's concatenations into the tests' bodies, where its -O3
    # range analysis raises false -Wstringop-overflow and -Warray-bounds (GCC bug 105651, the
    # family of the -Wrestrict one of the top-level CMakeLists.txt).
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      target_compile_options(${name} PRIVATE -Wno-stringop-overflow -Wno-array-bounds)
    endif()
  endif()
  gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                       PROPERTIES ENVIRONMENT "MG_CLI=$<TARGET_FILE:mergeguard>"
                       DISCOVERY_TIMEOUT 60)
  add_dependencies(${name} mergeguard)
endfunction()
