// RCPP's reading of the world, shared by its stages (planner/rcpp_planner.h): the contexts of the
// Definition 1 and 2 formulas at one decision instant, and how it predicts the other vehicles
// (spec §5-§6, docs/planner.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "planner/definition1.h"
#include "planner/definition2.h"
#include "planner/merge_path.h"
#include "planner/planner.h"

namespace mg {

// RCPP's reference paths: sampled every kPathStepM from kPathBehindM behind the ego.
inline constexpr double kPathBehindM = 10.0;
inline constexpr double kPathStepM = 1.0;

// The merge duration RCPP plans with: its own rho_m, but never below the rules' (the traffic
// code's rho_m, public like the speed limit): a merge planned for a shorter rho than the judge's
// is a merge into a gap the judge finds too short (spec §8; docs/planner.md).
double planned_rho_m_s(const PlannerSetup& s);

Def1Context def1_context(const WorldSnapshot& w, double rho_s);
CoopContext coop_context(const WorldSnapshot& w);

// The observed acceleration of vehicle `id` (0 when it is not observed).
double observed_accel_mps2(const WorldSnapshot& w, int id);
// The vehicle `id` as observed, or nullptr when it is not seen.
const ObservedVehicle* observed_vehicle(const WorldSnapshot& w, int id);
// Whether vehicle `id` is seen accelerating harder than its declared a_accel^max, or braking
// harder than its b_max, beyond the tolerance the rules read them with (accel_tolerance_mps2),
// and whether either: Definition 1 rests on those limits.
bool accelerating_beyond_limit(const WorldSnapshot& w, int id);
bool accelerating_beyond_limit(const WorldSnapshot& w, const ObservedVehicle& o);
bool braking_beyond_limit(const WorldSnapshot& w, int id);
bool beyond_declared_limits(const WorldSnapshot& w, int id);

// A target-lane leader as leader_track predicts it, behind the vehicle ahead of it in `lane`.
Track predicted_leader(const WorldSnapshot& w, const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& l,
                       double horizon_s);
// The LeaderHorizon of a prediction needed for horizon_s (the rest of a merge).
LeaderHorizon leader_horizon(const WorldSnapshot& w, double horizon_s);

// The P_c bound toward a vehicle `o` the ego merges behind (RCPP §II-C, spec §6), the ego reaching
// P_c at v_at while `o` is predicted at (x_o, v_o): x_o less D_lon, minus P_c; >= 0 while it holds.
double leader_bound_margin_m(const PlannerSetup& s, const MainLaneVehicle& o, double x_o_m, double v_o_mps, double v_at_mps,
                             double pc_m);

// Whether braking at b_min (or at brake_mps2) still stops the ego before the side lane's end, with
// one planner cycle of travel in hand for the speed controller, whose proportional tail stops the
// ego a little later than constant braking would (by centimetres with weak brakes at speed: an
// abort decided with less to spare halted past the end).
bool can_still_halt(const WorldSnapshot& w);
bool can_still_halt(const WorldSnapshot& w, double brake_mps2);

// When the ego on `ramp` reaches X = x_m from where it is now (nullopt: never).
std::optional<double> time_to_reach_s(const WorldSnapshot& w, const SpeedRamp& ramp, double x_m);

// The vehicles of the other main lanes, for the occupancy check (GapTracks::beside).
std::vector<BesideTrack> beside_tracks(const WorldSnapshot& w);

// Where a vehicle is after t_s at its observed speed (never backward).
double constant_speed_x(const ObservedVehicle& o, double t_s);

// The room a merge from standstill needs ahead of the halted ego: the distance from the start of
// a comfortable sigmoid at kStandstillMergeSpeedMps to the side-lane exit, plus kSideExitMarginM
// (Def. 1.3).
inline constexpr double kStandstillMergeSpeedMps = 5.0;
double standstill_merge_length_m(const PlannerSetup& s);

// |accel| the speed controller may use from current_mps toward target_mps: a_accel^max or b_min.
double accel_limit_toward(const PlannerSetup& s, double current_mps, double target_mps);

}  // namespace mg
