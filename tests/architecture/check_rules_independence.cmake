# cmake -DGRAPH=<module_graph.cmake> -DROOT=mg_rules -P check_rules_independence.cmake
# Fails (FATAL_ERROR, non-zero exit) if ROOT's link closure holds a forbidden module, or if a
# source of ROOT or of a project library in its closure includes a forbidden module's header.
cmake_minimum_required(VERSION 3.22)
include(${GRAPH})

set(forbidden_targets mg_planner mg_sim mg_fuzz mg_cli)
set(forbidden_dirs planner sim fuzz cli)

# Aliases (mergeguard::<export name>) to targets.
foreach(t ${MG_TARGETS})
  set(target_of_mergeguard::${MG_EXPORT_${t}} ${t})
endforeach()

# Breadth-first link closure of ROOT, remembering through whom each target came in.
set(closure ${ROOT})
set(queue ${ROOT})
set(via_${ROOT} "${ROOT}")
while(queue)
  list(POP_FRONT queue t)
  foreach(dep ${MG_LINKS_${t}})
    if(DEFINED target_of_${dep})
      set(dep ${target_of_${dep}})
    endif()
    if(dep STREQUAL "" OR dep IN_LIST closure)
      continue()
    endif()
    list(APPEND closure ${dep})
    set(via_${dep} "${via_${t}} -> ${dep}")
    if(DEFINED MG_LINKS_${dep})
      list(APPEND queue ${dep})
    endif()
  endforeach()
endwhile()

set(errors "")
foreach(t ${forbidden_targets})
  if(t IN_LIST closure)
    string(APPEND errors "  ${ROOT} links ${t}: ${via_${t}}\n")
  endif()
endforeach()

# Headers: every source of a project library in the closure (ROOT's own module and, e.g., core).
string(JOIN "|" dirs_regex ${forbidden_dirs})
set(include_regex "#[ \t]*include[ \t]*[\"<](mergeguard/)?(${dirs_regex})/[^\">]*[\">]")
foreach(t ${closure})
  if(NOT DEFINED MG_SOURCE_DIR_${t} OR t IN_LIST forbidden_targets)  # a forbidden link is reported above
    continue()
  endif()
  file(GLOB sources ${MG_SOURCE_DIR_${t}}/*.h ${MG_SOURCE_DIR_${t}}/*.cpp ${MG_SOURCE_DIR_${t}}/*.h.in)
  foreach(f ${sources})
    file(STRINGS ${f} lines REGEX "${include_regex}")
    foreach(line ${lines})
      string(STRIP "${line}" line)
      string(APPEND errors "  ${f} (module of ${t}, linked by ${via_${t}}): ${line}\n")
    endforeach()
  endforeach()
endforeach()

if(errors)
  message(FATAL_ERROR "rules/ must not depend on planners, the simulator, the fuzzer or the CLI:\n${errors}")
endif()
list(JOIN closure ", " shown)
message(STATUS "${ROOT} link closure: ${shown}; no planner/, sim/, fuzz/ or cli/ include in its modules")
