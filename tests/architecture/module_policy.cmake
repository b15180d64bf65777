# The allowed direction of every dependency between mergeguard's modules, checked by
# check_module_dependencies.cmake on the link graph CMake resolved and on every #include of every
# library source. A module may depend on the modules listed for it (its link closure may hold
# nothing else of the project, and its sources include headers of nothing else); anything not
# listed is forbidden. The data flow these follow is one way:
#
#   scenario -> planner -> sim (dynamics, behaviours, channel, trace) -> check (observe, judge)
#            -> rules (situations, rules, liability) -> report -> audit / paper / fuzz -> league -> cli
#
# rules/ judges an observable trace alone (it knows no planner and no simulator), so that a
# recording (recording/, audit/) is judged exactly as a simulated run; the simulator simulates
# and judges nothing.
set(MG_MODULES core recording planner sim rules check report audit paper fuzz league cli)
set(MG_ALLOWED_core "")
set(MG_ALLOWED_recording core)
set(MG_ALLOWED_planner core)
set(MG_ALLOWED_sim planner core)
set(MG_ALLOWED_rules core)
set(MG_ALLOWED_check rules sim planner core)
set(MG_ALLOWED_report rules core)
set(MG_ALLOWED_audit report recording rules core)
set(MG_ALLOWED_paper check report rules sim planner core)
set(MG_ALLOWED_fuzz check report rules sim planner core)
set(MG_ALLOWED_league fuzz check report rules sim planner core)
set(MG_ALLOWED_cli audit paper league fuzz check report recording rules sim planner core)
