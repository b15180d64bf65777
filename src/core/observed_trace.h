// The observable trace: what anyone watching the road and the V2V channel could
// record of a merge, and nothing a planner says about itself: the input of the independent
// oracle, whose rule monitors are to read only this, its declarations and the rule parameters
// (docs/trace_format.md; `check --save-trace` writes one, the merge phases are read from it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.h"
#include "core/scenario.h"
#include "core/v2v_message.h"

namespace mg {

inline constexpr int kTraceFormatVersion = 1;

// One vehicle's observable state, road frame (X along the road, Y lateral, +Y left).
struct ObservedState {
  double x_m = 0.0;          // centre
  double y_m = 0.0;
  double yaw_rad = 0.0;      // heading from +X, counter-clockwise
  double vx_mps = 0.0;       // road-frame longitudinal speed (dX/dt)
  double vy_mps = 0.0;       // road-frame lateral speed (dY/dt)
  double accel_mps2 = 0.0;   // longitudinal acceleration
  bool operator==(const ObservedState&) const = default;
};

// What a vehicle declares about itself before the merge: its size and the limits it promises
// (spec §2), and whether it takes part in V2V. Index 0 of ObservedTrace::vehicles is the ego.
struct VehicleDeclaration {
  int id = 0;                // 0 = ego, >= 1 main-lane vehicles
  VehicleSize size;
  Limits limits;
  bool v2v_capable = false;
  bool operator==(const VehicleDeclaration&) const = default;
};

struct ObservedStep {
  double time_s = 0.0;
  std::vector<ObservedState> vehicles;  // same order as ObservedTrace::vehicles
  bool operator==(const ObservedStep&) const = default;
};

// The V2V traffic as the channel saw it: every message sent, and for each its delivery or loss.
enum class ChannelEventKind { kSent, kDelivered, kLost };
struct ChannelEvent {
  double time_s = 0.0;
  ChannelEventKind kind = ChannelEventKind::kSent;
  V2vMessage message;
  bool operator==(const ChannelEvent&) const = default;
};

// The parameters a trace is judged with: RSS's and the rules' own (never the planner's).
struct JudgeParams {
  RssParams rss;
  RuleParams rules;
  bool operator==(const JudgeParams&) const = default;
};

struct ObservedTrace {
  std::string name = "unnamed";          // scenario or recording name, for reports
  std::string source;                    // who recorded it: "mergeguard simulate (planner rcpp)", a dataset id ...
  Road road;
  std::vector<VehicleDeclaration> vehicles;  // [0] = ego
  JudgeParams params;
  std::vector<ObservedStep> steps;       // strictly increasing times
  std::vector<ChannelEvent> channel;     // non-decreasing times
  // What the planner said about itself (decisions, reasons; free-form for outside planners).
  // Reports show it beside the verdict; no rule reads it. Null when absent.
  nlohmann::json planner_annotations;
  bool operator==(const ObservedTrace&) const = default;

  std::size_t vehicle_count() const { return vehicles.size(); }
  // Index of the vehicle with this id, or -1.
  int index_of(int id) const;
};

std::string to_string(ChannelEventKind k);
// FNV-1a (64 bit, over whole words) of the bit patterns of every step's time and observed states: equal traces
// have equal digests (reports print it; determinism checks compare it).
std::uint64_t trace_digest(const ObservedTrace& t);

}  // namespace mg
