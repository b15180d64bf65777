// The fuzzer's parametrisation of a merge scenario and its documented, realistic ranges
// (docs/fuzzing.md "Generated scenarios"). Both the RapidCheck generator (scenario_gen.h) and
// the libFuzzer byte decoder (byte_scenario.h) draw a ScenarioSpec inside these ranges;
// assemble_scenario turns it into a Scenario that always passes the loader's validation.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scenario.h"
#include "fuzz/round_real.h"

namespace mg::fuzz {

namespace range {
// Road (spec §2).
inline constexpr RealRange kLaneWidth{3.0, 4.0, 3.5, 0.05};           // m
inline constexpr RealRange kSideLaneStart{-100.0, 0.0, 0.0, 10.0};    // m
inline constexpr RealRange kSideLaneLength{100.0, 400.0, 300.0, 10.0};// m, extended if the ego could not stop
inline constexpr RealRange kSpeedLimit{20.0, 36.1, 33.3, 0.1};        // m/s (72-130 km/h)
// Ego.
inline constexpr RealRange kEgoOffset{0.0, 100.0, 0.0, 1.0};          // m after the side lane start
inline constexpr RealRange kEgoLateralOffset{-0.5, 0.5, 0.0, 0.05};   // m from the side lane centre, see below
inline constexpr double kEgoEdgeClearanceM = 0.3;  // the offset is capped so the ego starts this far inside its lane
inline constexpr RealRange kEgoSpeed{0.0, 36.0, 20.0, 0.1};           // m/s, capped at the speed limit
inline constexpr RealRange kEgoLength{3.8, 5.5, 4.8, 0.1};            // m
inline constexpr RealRange kEgoWidth{1.6, 2.1, 1.9, 0.05};            // m
inline constexpr RealRange kMass{900.0, 2500.0, 1500.0, 10.0};        // kg; yaw inertia = 1.5 m^2 x mass
inline constexpr RealRange kCgToFront{1.0, 1.6, 1.2, 0.05};           // m
inline constexpr RealRange kCgToRear{1.2, 1.8, 1.6, 0.05};            // m
inline constexpr RealRange kCornering{50000.0, 120000.0, 80000.0, 1000.0};  // N/rad
// Declared limits (ego and main-lane vehicles).
inline constexpr RealRange kAccelMax{1.0, 4.0, 2.0, 0.1};             // m/s^2
inline constexpr RealRange kBrakeMin{2.0, 6.0, 4.0, 0.1};             // m/s^2
inline constexpr RealRange kBrakeMaxExtra{0.0, 4.0, 4.0, 0.1};        // brake_max = brake_min + this
inline constexpr RealRange kLatAccelMax{0.1, 0.5, 0.2, 0.05};         // m/s^2
inline constexpr RealRange kLatBrakeMin{0.4, 1.5, 0.8, 0.1};          // m/s^2
// V2V.
inline constexpr RealRange kEgoLatency{0.0, 0.5, 0.1, 0.01};          // s
inline constexpr RealRange kEgoLoss{0.0, 0.3, 0.0, 0.01};             // probability
inline constexpr RealRange kLatency{0.0, 1.0, 0.1, 0.01};             // s
inline constexpr RealRange kLoss{0.0, 1.0, 0.0, 0.05};                // probability
// Main-lane vehicles.
inline constexpr RealRange kFirstOffset{-80.0, 120.0, 0.0, 0.5};      // m, first vehicle of a lane vs ego X
inline constexpr RealRange kGap{1.0, 150.0, 20.0, 0.5};               // m beyond the RSS safe distance behind the previous one
inline constexpr RealRange kSpeed{0.0, 40.0, 20.0, 0.1};              // m/s, capped at 1.1 x speed limit
inline constexpr RealRange kLength{3.5, 18.0, 4.8, 0.1};              // m (cars to trucks)
inline constexpr RealRange kWidth{1.6, 2.55, 1.9, 0.05};              // m
inline constexpr RealRange kHeight{1.4, 4.0, 1.5, 0.1};               // m
inline constexpr RealRange kDesiredSpeedDelta{-5.0, 5.0, 0.0, 0.5};   // m/s vs initial; 0 = "initial speed"
inline constexpr RealRange kHeadway{0.8, 2.5, 1.5, 0.1};              // s (IDM T)
inline constexpr RealRange kMinGap{1.0, 5.0, 2.0, 0.5};               // m (IDM s0)
inline constexpr RealRange kComfortBrake{1.0, 4.0, 2.0, 0.5};         // m/s^2 (IDM b)
inline constexpr RealRange kSegment{0.5, 5.0, 2.0, 0.5};              // s (bounded random)
inline constexpr std::uint64_t kBehaviourSeedMax = 1000;
// Non-compliance (scripted acts for liability tests).
inline constexpr RealRange kNcStart{0.0, 15.0, 0.0, 0.5};             // s
inline constexpr RealRange kNcDuration{0.5, 20.0, 20.0, 0.5};         // s
inline constexpr RealRange kNcExcess{0.5, 6.0, 2.0, 0.5};             // m/s^2 beyond the declared limit
// Parameters.
inline constexpr RealRange kResponseTime{0.1, 1.0, 0.5, 0.05};        // s (RSS T)
inline constexpr RealRange kMergeDuration{2.0, 8.0, 4.0, 0.1};        // s (rho_m)
inline constexpr RealRange kCommThreshold{0.3, 2.0, 1.0, 0.05};       // s (rho_c)
inline constexpr RealRange kHorizon{5.0, 30.0, 5.0, 0.5};             // s; shrinks toward short runs
// Targeted families (fuzz/scenario_families.h): the ego beside a V2V partner (Definition 2).
// Offsets are the partner's X relative to the ego's.
inline constexpr RealRange kCoopEgoSpeed{8.0, 32.0, 20.0, 0.1};       // m/s
inline constexpr RealRange kCoopSpeedDelta{-4.0, 4.0, 0.0, 0.1};      // m/s, a partner behind vs ego
inline constexpr RealRange kCoopAheadSpeedDelta{-1.5, 2.5, 0.5, 0.1}; // m/s, a partner ahead vs ego: farther or faster ones leave a Def. 1 gap behind
inline constexpr RealRange kCoopBehindOffset{-40.0, -2.0, -20.0, 0.5};// m: partner behind, ego ahead (Def. 2.1)
inline constexpr RealRange kCoopAheadOffset{-4.0, 12.0, 4.0, 0.5};    // m: partner ahead, ego behind (Def. 2.2)
inline constexpr RealRange kFollowerOffset{-80.0, -15.0, -40.0, 0.5};  // m: a follower behind the ego (no V2V needed)
inline constexpr RealRange kCoopLatency{0.0, 0.6, 0.1, 0.01};         // s, the partner's link: an answer later than rho_c is Def. 2.3's fallback, which latency up to 1 s in the uniform family already reaches
inline constexpr RealRange kCoopLoss{0.0, 0.5, 0.0, 0.05};            // probability, drawn on one link in four
inline constexpr RealRange kOverbrakeStart{0.0, 6.0, 1.0, 0.5};       // s: the partner's over-braking burst ...
inline constexpr RealRange kOverbrakeDuration{0.5, 4.0, 1.0, 0.5};    // s: ... and its length
// rcpp-coop tries Definition 2 at rho_m only (longer merges are Definition 1's): a rho_m below the
// shortest trackable sigmoid (about 4 s on a 3.5 m lane) or a short rho_c leave no Def. 2 candidate.
inline constexpr RealRange kCoopMergeDuration{4.0, 5.5, 4.0, 0.1};    // s (rho_m)
inline constexpr RealRange kCoopCommThreshold{0.8, 2.0, 1.5, 0.05};   // s (rho_c)
inline constexpr RealRange kFamilyHorizon{12.0, 30.0, 15.0, 0.5};     // s: the exchange, the merge, and a fallback or halt after it
}  // namespace range

struct LimitsSpec {
  double accel_max_mps2 = 2.0;
  double brake_min_mps2 = 4.0;
  double brake_max_extra_mps2 = 4.0;
  double lat_accel_max_mps2 = 0.2;
  double lat_brake_min_mps2 = 0.8;
};

struct V2vSpec {
  bool capable = false;
  double latency_s = 0.1;
  double loss_prob = 0.0;
};

struct RoadSpec {
  double lane_width_m = 3.5;
  int main_lanes = 1;
  double side_lane_start_x_m = 0.0;
  double side_lane_length_m = 300.0;
  double speed_limit_mps = 33.3;
};

struct EgoSpec {
  double offset_m = 0.0;          // X after the side lane start
  double lateral_offset_m = 0.0;  // Y from the side lane centre
  double speed_mps = 20.0;
  double length_m = 4.8;
  double width_m = 1.9;
  LimitsSpec limits;
  V2vSpec v2v;
  double mass_kg = 1500.0;
  double cg_to_front_m = 1.2;
  double cg_to_rear_m = 1.6;
  double cornering_front_npr = 80000.0;
  double cornering_rear_npr = 80000.0;
};

struct VehicleSpec {
  int lane = 0;                   // clamped to the road's main lanes
  double first_offset_m = 0.0;    // used by the first vehicle of its lane
  double gap_m = 20.0;            // used by the others: slack beyond the RSS distance (RCPP eq. 1)
  double speed_mps = 20.0;
  double length_m = 4.8;
  double width_m = 1.9;
  double height_m = 1.5;
  LimitsSpec limits;
  BehaviourType behaviour = BehaviourType::kConstantSpeed;
  double desired_speed_delta_mps = 0.0;
  double time_headway_s = 1.5;
  double min_gap_m = 2.0;
  double comfort_brake_mps2 = 2.0;
  std::uint64_t behaviour_seed = 1;
  double segment_s = 2.0;
  V2vSpec v2v;
  NonComplianceType noncompliance = NonComplianceType::kNone;
  double nc_start_s = 0.0;
  double nc_duration_s = 20.0;
  double nc_excess_mps2 = 2.0;
};

struct ParamsSpec {
  double response_time_s = 0.5;
  double merge_duration_s = 4.0;
  double comm_threshold_s = 1.0;
  double horizon_s = 5.0;
};

struct ScenarioSpec {
  RoadSpec road;
  EgoSpec ego;
  std::vector<VehicleSpec> vehicles;
  ParamsSpec params;
};

// Places the vehicles (per lane, in order: the first at first_offset_m from the ego, the next
// gap_m beyond the RSS longitudinal safe distance ahead of the previous one, so that every lane
// starts RSS-safe), numbers them 1..n, caps speeds, resets fields
// the chosen behaviour or non-compliance does not use, and extends the side lane so that the
// ego can always stop before its end (the scenario is never unwinnable by construction).
Scenario assemble_scenario(const ScenarioSpec& spec);


}  // namespace mg::fuzz
