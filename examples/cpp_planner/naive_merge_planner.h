// An outside planner written against the installed mergeguard package only: it keeps the lane it
// starts in until a fixed time, then merges into the rightmost main lane along one sigmoid at its
// initial speed, whatever the traffic. Deliberately naive (no gap, no RSS, no braking) so that a
// campaign finds what it gets wrong.
#pragma once

#include <optional>
#include <string>

#include <mergeguard/mergeguard.h>

namespace example {

inline constexpr const char* kNaivePlannerName = "example-naive";

class NaiveMergePlanner : public mg::Planner {
 public:
  std::string name() const override { return kNaivePlannerName; }
  mg::PlanOutput plan(const mg::WorldSnapshot& world) override;

  static constexpr double kMergeTimeS = 1.0;     // when it leaves its lane
  static constexpr double kMergeAheadM = 40.0;   // sigmoid midpoint P_c ahead of where it starts
  static constexpr double kKappaPerM = 0.15;     // sigmoid slope

 private:
  std::optional<double> start_y_m_;    // the lane it starts in (first cycle)
  std::optional<double> merge_pc_m_;   // P_c, fixed when the merge starts
  bool merged_ = false;                // reached the main lane (stays so)
};

// Registers NaiveMergePlanner as "example-naive" (call once, before the campaign or cli_main).
void register_naive_merge_planner();

}  // namespace example
