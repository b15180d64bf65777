// The merge scenario shared by the whole suite: road (spec §2), ego, main-lane vehicles with
// declared limits, behaviours and V2V, and the parameters. JSON format: docs/scenario_format.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.h"

namespace mg {

inline constexpr int kScenarioFormatVersion = 1;
inline constexpr std::size_t kMaxVehicles = 64;  // hostile-input bound, documented

// Road frame: X along the road, Y lateral (+Y left). Main lane centre Y = 0; extra main lanes
// to the left at Y = k W; side lane (on-ramp) centre Y = -W from side_lane_start_x_m to
// side_lane_end_x_m, where it physically ends.
struct Road {
  double lane_width_m = 3.5;          // W, [2, 6]
  int main_lanes = 1;                 // [1, 4]
  double side_lane_start_x_m = 0.0;   // [-1e4, 1e5]
  double side_lane_end_x_m = 300.0;   // > side_lane_start_x_m
  double speed_limit_mps = 33.34;     // (0, 100]
  bool operator==(const Road&) const = default;
  double side_lane_y_m() const { return -lane_width_m; }
};

// Declared (promised) limits of a vehicle: positive magnitudes (spec §2).
struct Limits {
  double accel_max_mps2 = 2.0;        // a_accel^max, [0, 15]
  double brake_min_mps2 = 4.0;        // a_brake^min, (0, brake_max]
  double brake_max_mps2 = 8.0;        // a_brake^max, [brake_min, 15]
  double lat_accel_max_mps2 = 0.2;    // a_lat^max, [0, 10]
  double lat_brake_min_mps2 = 0.8;    // a_lat,brake^min, (0, 10]
  bool operator==(const Limits&) const = default;
};

struct V2v {
  bool capable = false;
  double latency_s = 0.1;             // one-way message latency, [0, 10]
  double loss_prob = 0.0;             // probability that a message is lost, [0, 1]
  bool operator==(const V2v&) const = default;
};

enum class BehaviourType {
  kConstantSpeed,   // holds its speed (brakes only when RSS demands)
  kIdm,             // Intelligent Driver Model
  kRssFollower,     // keeps D_lon behind whoever is ahead, the merged ego included
  kBoundedRandom,   // piecewise-constant accelerations inside its declared limits (seeded)
  kCooperative,     // IDM that answers V2V requests after its latency and tracks v_o*
  kNonResponsive,   // IDM that never answers V2V
};

struct Behaviour {
  BehaviourType type = BehaviourType::kIdm;
  double desired_speed_mps = -1.0;    // IDM / constant: < 0 means "initial speed", else [0, 100]
  double time_headway_s = 1.5;        // IDM T, [0, 10]
  double min_gap_m = 2.0;             // IDM s0 (bumper to bumper), [0, 100]
  double comfort_brake_mps2 = 2.0;    // IDM b, (0, 15]
  std::uint64_t seed = 1;             // bounded-random draw seed
  double segment_s = 2.0;             // bounded-random segment duration, [0.1, 100]
  bool operator==(const Behaviour&) const = default;
};

enum class NonComplianceType {
  kNone,
  kExceedAccel,   // accelerates at accel_mps2 (> declared accel_max) during [start, start+duration]
  kExceedBrake,   // brakes at brake_mps2 (> declared brake_max) during [start, start+duration]
  kRenege,        // accepts a cooperation request and does not yield
};

struct NonCompliance {
  NonComplianceType type = NonComplianceType::kNone;
  double start_time_s = 0.0;          // [0, 3600]
  double duration_s = 1e9;            // (0, 1e9]
  double accel_mps2 = 0.0;            // magnitude used by exceed_accel / exceed_brake, [0, 30]
  bool operator==(const NonCompliance&) const = default;
};

struct VehicleSize {
  double length_m = 4.8;              // (0, 30]
  double width_m = 1.9;               // (0, 5]
  double height_m = 1.5;              // (0, 6]
  bool operator==(const VehicleSize&) const = default;
};

// A main-lane vehicle at t = 0.
struct MainVehicle {
  int id = 1;                         // unique, >= 1 (the ego is 0)
  int lane = 0;                       // main lane index, 0 = rightmost main lane
  double x_m = 0.0;                   // centre, road frame
  double speed_mps = 20.0;            // [0, 100]
  VehicleSize size;
  Limits limits;
  Behaviour behaviour;
  V2v v2v;
  NonCompliance noncompliance;
  bool operator==(const MainVehicle&) const = default;
};

// Ego single-track parameters (spec §7); defaults are a mid-size passenger car.
struct EgoDynamics {
  double mass_kg = 1500.0;            // [100, 50000]
  double yaw_inertia_kgm2 = 2250.0;   // [10, 1e6]
  double cg_to_front_m = 1.2;         // l_f, (0, 10]
  double cg_to_rear_m = 1.6;          // l_r, (0, 10]
  double cornering_front_npr = 80000; // C_f, N/rad, (0, 1e7]
  double cornering_rear_npr = 80000;  // C_r, N/rad, (0, 1e7]
  double steer_max_rad = 0.5;         // (0, 1.5]
  double steer_rate_max_radps = 0.7;  // (0, 10]
  double wheelbase_m() const { return cg_to_front_m + cg_to_rear_m; }  // L = l_f + l_r
  bool operator==(const EgoDynamics&) const = default;
};

struct Ego {
  double x_m = 0.0;
  double y_m = -3.5;                  // default: side lane centre (-W)
  double speed_mps = 20.0;            // [0, 100]
  VehicleSize size;
  Limits limits;
  V2v v2v;
  EgoDynamics dynamics;
  bool operator==(const Ego&) const = default;
};

// What a planner may know before it starts (the exec protocol's `reset`): the road,
// its own vehicle's declarations and dynamics, and the parameters. Nothing of the other
// vehicles, whose behaviours no planner can observe.
struct PlannerSetup {
  Road road;
  Ego ego;
  Params params;
  bool operator==(const PlannerSetup&) const = default;
};

// A scenario: the planner's setup plus the other vehicles, each with its behaviour.
struct Scenario : PlannerSetup {
  std::string name = "unnamed";
  std::string description;
  std::vector<MainVehicle> vehicles;
  bool operator==(const Scenario&) const = default;

  // Index into `vehicles` of the vehicle with this id, or -1.
  int index_of(int id) const;
};

// Loading validates everything once (types, ranges, unknown keys, unique ids, side lane that
// ends after it starts, no initial overlap); errors are InputError("<source>", "/json/path", ...).
Scenario scenario_from_json(const nlohmann::json& j, const std::string& source);
Scenario load_scenario(const std::string& path);
nlohmann::json scenario_to_json(const Scenario& s);
// Writes atomically (temporary file, flush, rename).
void write_scenario(const Scenario& s, const std::string& path);

// The road, declared limits and vehicle size as the scenario reads them (same keys, defaults and
// ranges), shared with the trace format (core/observed_trace_json.h) so that both validate a
// declaration alike. `path` is the object's JSON path, for errors. The size object holds only
// length_m, width_m, height_m (a scenario's vehicles carry them flat instead).
Road road_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
Limits limits_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
VehicleSize vehicle_size_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json road_to_json(const Road& road);
nlohmann::json limits_to_json(const Limits& l);
nlohmann::json vehicle_size_to_json(const VehicleSize& size);

std::string to_string(BehaviourType t);
std::string to_string(NonComplianceType t);

}  // namespace mg
