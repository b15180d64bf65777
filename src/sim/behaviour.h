// Main-lane traffic (spec §7): longitudinal behaviours on the lane centre, the cooperative
// V2V responder of Definition 2, and the scripted non-compliance overlay used by liability tests.
#pragma once

#include <optional>

#include "core/observed_trace_json.h"
#include "core/params.h"
#include "core/scenario.h"
#include "core/v2v_message.h"
#include "core/vehicle_state.h"
#include "sim/splitmix64.h"

namespace mg {

// A vehicle scripted to exceed its a_accel^max (NonComplianceType::kExceedAccel) stops
// accelerating at this speed (360 km/h): a breach held for 20 s at 10 m/s2 would otherwise reach
// speeds no road vehicle drives, and a saved trace no reader accepts (kMaxTraceSpeedMps).
inline constexpr double kMaxScriptedSpeedMps = 100.0;
static_assert(kMaxScriptedSpeedMps + 20.0 < kMaxTraceSpeedMps, "one step of the harshest breach stays in the trace's range");

// The vehicle directly ahead in the same lane (centre-to-centre distance, its speed and what
// it declares), as seen by one main-lane vehicle.
struct Leader {
  int id = 0;                     // 0 = the ego
  double distance_m = 0.0;        // centre to centre, > 0
  double speed_mps = 0.0;
  double length_m = 0.0;
  double brake_max_mps2 = 0.0;    // the leader's declared a_brake^max
};

// Who the main-lane vehicle `index` follows: the nearest vehicle ahead on its lane (main_only)
// and, once the ego's box overlaps the lane laterally (the merged or merging ego), the nearer of
// that and the ego (with_ego).
struct Leaders {
  std::optional<Leader> with_ego;
  std::optional<Leader> main_only;
};
Leaders find_leaders(const Scenario& s, const std::vector<VehicleState>& others, std::size_t index,
                     const VehicleState& ego);

// Each lane's vehicles in X order, kept from step to step (vehicles rarely change it), so that
// the leaders cost O(1) per vehicle instead of find_leaders' O(n) scan.
class LaneOrder {
 public:
  // Re-sorts every lane by (X, index) after the vehicles moved.
  void update(const Scenario& s, const std::vector<VehicleState>& others);
  // Exactly find_leaders(s, others, index, ego) for the states of the last update().
  Leaders leaders(const Scenario& s, const std::vector<VehicleState>& others, std::size_t index,
                  const VehicleState& ego) const;
  // Whether two vehicles of one lane overlap in the last update()'s states (as the scenario loader
  // judges t = 0: touching is not overlapping).
  // Neighbours in X order suffice: a vehicle whose centre lies between two overlapping ones
  // overlaps one of them.
  bool any_overlap(const Scenario& s, const std::vector<VehicleState>& others) const;

 private:
  std::vector<std::vector<std::size_t>> lanes_;  // vehicle indices by (X, index)
  std::vector<std::size_t> position_;            // of each vehicle in its lane
};

// Intelligent Driver Model (Treiber et al., 2000): a [1 - (v/v0)^4 - (s*/s)^2],
// s* = s0 + max(0, v T + v dv / (2 sqrt(a b))), s = bumper gap; a = max(accel_max, 0.5).
// The result is not yet clamped to the declared limits.
double idm_accel_mps2(double speed_mps, double desired_speed_mps, const std::optional<Leader>& leader,
                      double own_length_m, const Behaviour& b, const Limits& limits);

// RSS longitudinal danger against the leader: centre distance below D_lon with this vehicle
// as the rear one (RCPP eq. 1).
bool rss_unsafe_behind(double speed_mps, double own_length_m, const Limits& own, const Leader& leader,
                       const RssParams& rss);

// Advances a main-lane vehicle along its lane centre with constant acceleration; it never
// moves backwards (the speed stops at 0). Records the applied acceleration.
void advance_on_lane(VehicleState& s, double accel_mps2, double dt_s);

// What a driver sees at one step.
struct DriverInput {
  double time_s = 0.0;
  double speed_mps = 0.0;
  std::optional<Leader> leader;            // including the ego when it overlaps the lane
  std::optional<Leader> leader_main_only;  // ignoring the ego
  bool ego_in_lane = false;                // ego centre within 0.5 m of this lane's centre
};

// One main-lane vehicle's driver: its behaviour, its V2V answers and its scripted
// non-compliance. Deterministic: its only randomness is the behaviour's seed.
class MainLaneDriver {
 public:
  MainLaneDriver(const MainVehicle& spec, const Road& road, const Params& params);

  // The answer to a delivered cooperation request (accept or refuse), or nothing
  // (non-responsive). Cooperative: accepts when 0 <= v_o* <= speed limit, v_o* is reachable
  // within rho_c at brake_min (ego ahead) or accel_max (ego behind), and its cooperating law
  // keeps the promise behind `leader` (the vehicle ahead of it in its lane, predicted at its
  // current speed) from t_r + rho_c + T to t_r + rho_c + rho_m: a driver does not promise a
  // speed the traffic ahead of it will not let it reach (RCPP Def. 2.2 B counts on it).
  std::optional<V2vMessage> answer(const V2vMessage& request, double time_s, double speed_mps,
                                   const std::optional<Leader>& leader = std::nullopt);

  // Longitudinal acceleration to apply this step.
  double accel_mps2(const DriverInput& in);

  // True during a scripted exceed_accel / exceed_brake window, or while reneging.
  bool non_compliant(double time_s) const;

  bool cooperating() const { return mode_ == Mode::kCooperating; }

 private:
  enum class Mode { kNormal, kCooperating, kReneging };

  double behaviour_accel(const DriverInput& in);
  // Definition 2's cooperating law toward `target`, behind `leader` (clamped to the limits).
  double cooperating_accel(double speed_mps, double target_mps, CoopCase c, const std::optional<Leader>& leader) const;
  bool keeps_promise(const V2vMessage& request, double time_s, double speed_mps,
                     const std::optional<Leader>& leader) const;
  double desired_speed() const;
  bool in_window(double time_s) const;

  MainVehicle spec_;
  Road road_;
  Params params_;
  SplitMix64 rng_;
  long long segment_ = -1;
  double segment_accel_mps2_ = 0.0;
  Mode mode_ = Mode::kNormal;
  double coop_target_mps_ = 0.0;
  CoopCase coop_case_ = CoopCase::kEgoAhead;
  double coop_since_s_ = 0.0;
};

}  // namespace mg
