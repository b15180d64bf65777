# cmake -P script of the CTest test package.install_and_build_example (tests/package/CMakeLists.txt):
#   1. cmake --install MG_BUILD_DIR --prefix WORK/prefix        (nothing is rebuilt)
#   2. configure and build examples/cpp_planner against it with find_package(mergeguard)
#   3. the installed mergeguard binary refuses --planner example-naive (exit 2): the control
#   4. the example's cpp_planner_cli runs a fuzz campaign with it (exit 0 or 1, the summary names
#      it), replays the cases the campaign wrote, plans and checks a scenario with it
#   5. the example's own GoogleTest/RapidCheck suite passes
cmake_minimum_required(VERSION 3.22)  # policies of a script run with -P

foreach(var MG_BUILD_DIR MG_EXAMPLE_DIR MG_SCENARIO MG_WORK_DIR MG_GENERATOR MG_CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()

set(prefix ${MG_WORK_DIR}/prefix)
set(example_build ${MG_WORK_DIR}/example-build)
set(corpus ${MG_WORK_DIR}/corpus)
file(REMOVE_RECURSE ${MG_WORK_DIR})
file(MAKE_DIRECTORY ${corpus})

# run(<name> <allowed exit codes> COMMAND ...): runs the command, output to <name>.out in the
# work directory; fails the test (showing the output) on another exit code. Sets ${name}_output.
function(run name allowed)
  cmake_parse_arguments(ARG "" "" "COMMAND" ${ARGN})
  message(STATUS "package test: ${name}: ${ARG_COMMAND}")
  execute_process(COMMAND ${ARG_COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(WRITE ${MG_WORK_DIR}/${name}.out "${out}\n--- stderr ---\n${err}")
  if(NOT rc IN_LIST allowed)
    message(FATAL_ERROR "package test: ${name} exited ${rc} (expected one of ${allowed})\n${out}\n${err}")
  endif()
  set(${name}_output "${out}" PARENT_SCOPE)
  set(${name}_stderr "${err}" PARENT_SCOPE)
endfunction()

run(install 0 COMMAND ${CMAKE_COMMAND} --install ${MG_BUILD_DIR} --prefix ${prefix})
foreach(f include/mergeguard/mergeguard.h include/mergeguard/planner/planner_registry.h
          include/mergeguard/cli/cli_main.h lib/cmake/mergeguard/mergeguardConfig.cmake
          lib/cmake/mergeguard/mergeguardConfigVersion.cmake lib/cmake/mergeguard/mergeguardTargets.cmake
          bin/mergeguard)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "package test: the install has no ${f}")
  endif()
endforeach()
file(READ ${prefix}/lib/cmake/mergeguard/mergeguardTargets.cmake targets)
if(targets MATCHES "INTERFACE_COMPILE_OPTIONS|INTERFACE_COMPILE_DEFINITIONS")
  message(FATAL_ERROR "package test: the exported targets force compile options or definitions on consumers")
endif()

run(configure 0 COMMAND ${CMAKE_COMMAND} -S ${MG_EXAMPLE_DIR} -B ${example_build} -G "${MG_GENERATOR}"
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${MG_BUILD_TYPE} -DCMAKE_CXX_COMPILER=${MG_CXX_COMPILER}
    "-DCMAKE_CXX_FLAGS=${MG_CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${MG_EXE_LINKER_FLAGS}")
run(build 0 COMMAND ${CMAKE_COMMAND} --build ${example_build} -j2)

# The control: without the registration the same name is refused, by --planner.
run(control 2 COMMAND ${prefix}/bin/mergeguard fuzz --planner example-naive --runs 1 --corpus ${MG_WORK_DIR}/control)
if(NOT control_stderr MATCHES "--planner: unknown planner .example-naive.")
  message(FATAL_ERROR "package test: the installed mergeguard did not refuse the planner by name\n${control_stderr}")
endif()

set(cli ${example_build}/cpp_planner_cli)
run(fuzz "0;1" COMMAND ${cli} fuzz --planner example-naive --runs 100 --seed 1 --jobs 1 --corpus ${corpus} --json)
string(JSON planner ERROR_VARIABLE json_error GET "${fuzz_output}" planner)
if(json_error OR NOT planner STREQUAL "example-naive")
  message(FATAL_ERROR "package test: the campaign summary names planner '${planner}' ${json_error}\n${fuzz_output}")
endif()
string(JSON scenarios GET "${fuzz_output}" scenarios)
if(NOT scenarios EQUAL 100)
  message(FATAL_ERROR "package test: the campaign ran ${scenarios} scenarios, not 100")
endif()
file(GLOB cases ${corpus}/*.json)
list(LENGTH cases case_count)
message(STATUS "package test: the campaign of example-naive wrote ${case_count} case(s)")
if(case_count GREATER 0)
  run(replay 0 COMMAND ${cli} replay ${corpus})
endif()
run(plan 0 COMMAND ${cli} plan ${MG_SCENARIO} --planner example-naive --json)
# The decision's reason is the example planner's own text: its code ran, not a built-in's.
if(NOT plan_output MATCHES "example-naive: keeping its lane")
  message(FATAL_ERROR "package test: plan does not show the example planner's decision\n${plan_output}")
endif()
run(check "0;1" COMMAND ${cli} check ${MG_SCENARIO} --planner example-naive --json)

if(EXISTS ${example_build}/naive_merge_planner_test)
  run(example_tests 0 COMMAND ${example_build}/naive_merge_planner_test)
else()
  message(STATUS "package test: GoogleTest not found by the example: its own suite not built")
endif()
message(STATUS "package test: passed")
