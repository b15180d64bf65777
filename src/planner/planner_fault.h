// A planner under test that misbehaves: an exec planner that does not answer in
// time, answers what the protocol does not allow, or exits mid-scenario. Thrown out of
// Planner::plan; a campaign records it as a failure of property planner_responds
// (fuzz/properties.h) and `check` as a violation, never as an error of mergeguard.
#pragma once

#include <stdexcept>
#include <string>

namespace mg {

// The kinds, used as the failure's rule name so that each gets its own corpus case.
inline constexpr const char* kFaultTimeout = "planner_timeout";  // no reply within --planner-timeout
inline constexpr const char* kFaultExit = "planner_exit";        // exited, crashed or could not restart
inline constexpr const char* kFaultReply = "planner_reply";      // not JSON, against the schema, NaN, unusable path

struct PlannerFault : std::runtime_error {
  PlannerFault(std::string kind_, double time_s_, const std::string& reason)
      : std::runtime_error(reason), kind(std::move(kind_)), time_s(time_s_) {}
  std::string kind;     // one of the kFault* names
  double time_s = 0.0;  // simulated time of the call (0 for reset)
};

}  // namespace mg
