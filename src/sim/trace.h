// What a simulation produced: every step's state of every vehicle, every planner decision and
// V2V event; compute_digest digests it (spec §7). The rule monitors judge only this and the
// scenario.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scenario.h"
#include "core/vehicle_state.h"
#include "planner/planner.h"

namespace mg {

struct TraceStep {
  double time_s = 0.0;
  VehicleState ego;
  std::vector<VehicleState> others;     // same order as Scenario::vehicles
  std::string ego_mode;                 // mode of the planner output in force (PlanOutput::mode)
  bool ego_proper_response = false;     // RSS override active this step
};

enum class EventKind {
  kDecision,        // new planner decision (mode change); detail = reason
  kMessageSent,     // V2V message left its sender
  kMessageLost,     // the channel dropped it
  kMessageDelivered,
  kMergeStart,      // ego begins to leave the side lane
  kMergeMidpoint,   // ego centre crosses the lane boundary
  kMergeComplete,   // ego centre within 0.2 m of the main lane centre, heading aligned
  kHalt,            // ego stopped (speed < 0.05 m/s)
  kResume,          // ego moving again after a halt
  kNonCompliance,   // a main-lane vehicle started a scripted non-compliant act
};

struct TraceEvent {
  double time_s = 0.0;
  EventKind kind = EventKind::kDecision;
  int vehicle_id = 0;        // actor (0 = ego)
  std::string detail;
  std::optional<V2vMessage> message;
};

struct Trace {
  std::string planner;
  std::vector<TraceStep> steps;
  std::vector<PlanRecord> decisions;    // every planner cycle's account of itself
  std::vector<TraceEvent> events;
};

std::string to_string(EventKind k);
nlohmann::json trace_to_json(const Trace& t);
// FNV-1a (64 bit) over the bit patterns of every step's time, states, mode and override flag;
// trace_to_json writes it. Computed on demand: a checked run is digested as its observable trace
// (core/observed_trace.h trace_digest), and a second pass over every run cost campaigns 2 %.
std::uint64_t compute_digest(const Trace& t);
// The digest as 16 lowercase hex digits (JSON numbers cannot hold 64 bits exactly everywhere).
std::string digest_hex(std::uint64_t digest);

}  // namespace mg
