// The RCPP planner (RCPP §II, spec §4-§6): each cycle, the RSS override first; a committed merge
// is followed along its sigmoid; otherwise Definition 1 picks a gap, v_e* and the sigmoid, and
// with cooperation enabled ("rcpp-coop") Definition 2 asks a V2V neighbour for v_o* when no
// Definition 1 gap exists; with neither, Definition 1.3 halts before the side lane's end.
// Decision rules and cost: docs/planner.md.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "planner/definition2.h"
#include "planner/planner.h"
#include "planner/return_path.h"
#include "planner/sigmoid.h"

namespace mg {

// A committed merge may be aborted (P_c bounds crossed) only while the ego has covered less than
// this fraction of its lateral move (from the side lane's centre, or from where it was when the
// merge was planned if that is nearer the main lane); later it completes, protected by the RSS
// override.
inline constexpr double kAbortLateralFraction = 0.25;

// The room a merge from standstill needs ahead of the halted ego: the distance from the start of
// a comfortable sigmoid at kStandstillMergeSpeed to the side-lane exit, plus kSideExitMarginM
// (Def. 1.3).
inline constexpr double kStandstillMergeSpeedMps = 5.0;
double standstill_merge_length_m(const Scenario& s);

// Definition 1 at one decision instant: the best gap and sigmoid over the merge durations.
struct Def1Plan {
  Decision decision;  // mode kDef1Merge, gap, v_e* interval and choice, P_c bounds/choice, kappa
  Sigmoid sigmoid;
  double ve_star_mps = 0.0;
};
// kRhoM: the configured merge duration (raised to a comfortable one); kLonger: the longer ones of
// kMergeDurationFactors, tried only after Definition 2 (the paper's order: Def. 1 at rho_m, then
// cooperation, then the extension). nullopt when no gap is feasible; `why` then gets the reasons.
enum class MergeDurations { kRhoM, kLonger };
std::optional<Def1Plan> plan_definition1(const WorldSnapshot& w, MergeDurations durations, std::string* why);

// Definition 2 request at one decision instant (excluding partners in `excluded`).
struct Def2Plan {
  Decision decision;  // mode kDef2Request, partner, v_o*, D*_lon, P_c bounds/choice, kappa
  Sigmoid sigmoid;
  VoStar vo;
  MainLaneVehicle partner;
  double ego_speed_after_mps = 0.0;  // the ego's speed during and after the exchange
};
std::optional<Def2Plan> plan_definition2(const WorldSnapshot& w, const std::map<int, double>& retry_after_s);

class RcppPlanner : public Planner {
 public:
  explicit RcppPlanner(bool cooperative) : cooperative_(cooperative) {}
  std::string name() const override { return cooperative_ ? "rcpp-coop" : "rcpp"; }
  PlanOutput plan(const WorldSnapshot& w) override;

 private:
  struct Merge {
    Sigmoid sigmoid;
    double target_speed_mps = 0.0;
    Decision decision;
    // Where the lateral move starts: the side lane's centre, or the ego's offset at the decision
    // if nearer the main lane (a merge planned while the ego is still on its way back from an
    // abort is not committed from its first cycle: it would then follow, at RSS distance, the
    // gap's follower it is about to pass, and stop behind it for good; a campaign finding).
    double start_y_m = 0.0;
    bool committed(double ego_y_m) const {
      const double move_m = sigmoid.offset_m + sigmoid.width_m - start_y_m;
      return ego_y_m - start_y_m >= kAbortLateralFraction * move_m;
    }
  };
  struct Pending {
    Def2Plan plan;
    double deadline_s = 0.0;
  };

  PlanOutput follow_merge(const WorldSnapshot& w);
  PlanOutput keep_main_lane(const WorldSnapshot& w);
  PlanOutput decide_in_side_lane(const WorldSnapshot& w);
  PlanOutput start_merge(const WorldSnapshot& w, const Sigmoid& s, double speed_mps, Decision d);
  std::vector<PathPoint> side_lane_path(const WorldSnapshot& w);  // may plan and keep return_
  bool committed_bounds_crossed(const WorldSnapshot& w) const;  // P_c bounds at predicted positions
  // The occupancy check of the rest of the merge with the gap vehicles as observed now.
  bool committed_occupancy_clear(const WorldSnapshot& w) const;
  double merge_target_speed_mps(const WorldSnapshot& w) const;  // v_e*, capped behind a braking leader
  double pc_bound_speed_mps(const WorldSnapshot& w, const std::vector<MainLaneVehicle>& lane,
                            const MainLaneVehicle& leader, double target_mps) const;
  void apply_override(const WorldSnapshot& w, PlanOutput& out) const;
  // `w` with each other vehicle's acceleration replaced by the harshest braking seen from it in
  // the last kBrakingMemoryS (rcpp_planner.cpp), updating seen_braking_.
  WorldSnapshot with_braking_memory(const WorldSnapshot& w);

  bool cooperative_;
  bool merged_ = false;
  std::optional<Merge> merge_;
  std::optional<Pending> pending_;
  std::optional<ReturnPath> return_;  // back to the side lane's centre (or a hold), kept until its end
  bool hold_pending_ = false;          // a shallow abort: the next side-lane path holds (plan_lateral_hold)
  std::optional<double> hold_y_m_;     // after that hold: the Y kept until the next merge
  std::map<int, double> retry_after_s_;  // partner id -> earliest time of a new request
  double no_merge_before_s_ = -1.0;       // after an abort: earliest time of a new merge
  double next_longer_merge_s_ = -1.0;     // next time the longer merge durations are searched
  struct SeenBraking {
    double accel_mps2 = 0.0;  // <= 0
    double time_s = 0.0;
  };
  std::map<int, SeenBraking> seen_braking_;  // vehicle id -> harshest recent braking
};

}  // namespace mg
