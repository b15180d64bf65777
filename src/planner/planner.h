// The one planner interface that the simulator, checker and fuzzer drive.
// A planner sees an observation (WorldSnapshot: time, its own state, the other vehicles'
// observable states and declarations, the V2V messages delivered to it, its setup: road, own
// declarations, parameters) and returns a command (PlanOutput: a reference path, a target speed
// and acceleration limit, V2V messages to send, and an optional account of itself for reports).
// Nothing in it is any one planner's vocabulary: RCPP's decision record is RCPP's annotation
// (planner/rcpp_decision.h). Planners register with register_planner (planner/planner_registry.h),
// built-in or not.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/demand.h"
#include "core/scenario.h"
#include "core/v2v_message.h"
#include "core/vehicle_state.h"

namespace mg {

// What a planner knows of a main-lane vehicle: its state and what it declares (size, limits,
// V2V capability). Behaviours and non-compliance are not observable.
struct ObservedVehicle {
  int id = 0;
  VehicleState state;
  VehicleSize size;
  Limits limits;
  bool v2v_capable = false;
};

struct WorldSnapshot {
  double time_s = 0.0;
  VehicleState ego;
  std::vector<ObservedVehicle> others;   // sorted by id
  std::vector<V2vMessage> inbox;         // messages delivered to the ego since the last cycle
  const PlannerSetup* setup = nullptr;   // road, the ego's declarations and dynamics, params (never null)
};

// A planner's own account of one cycle (RCPP's decision record, an exec planner's `annotation`):
// reports and saved traces show it beside the verdict; no rule reads it. It is serialized only
// when a report or trace asks, so a planner may keep it typed and cheap.
class PlanAnnotation {
 public:
  virtual ~PlanAnnotation() = default;
  virtual nlohmann::json to_json() const = 0;  // a JSON object
  // "label: value" lines for `mergeguard plan`'s human output; by default the JSON's members.
  virtual std::vector<std::pair<std::string, std::string>> describe() const;

 protected:
  PlanAnnotation() = default;
  PlanAnnotation(const PlanAnnotation&) = default;
  PlanAnnotation& operator=(const PlanAnnotation&) = default;
};

// The annotation of a planner that gives JSON (an exec planner's free-form object).
class JsonAnnotation final : public PlanAnnotation {
 public:
  explicit JsonAnnotation(nlohmann::json j) : json_(std::move(j)) {}
  nlohmann::json to_json() const override { return json_; }

 private:
  nlohmann::json json_;
};

struct PathPoint {
  double x_m = 0.0;
  double y_m = 0.0;
};

// The points (x, y_of(x)) at x_from, x_from + step, ... while clearly below x_to, then x_to:
// strictly increasing X.
template <class YOf>
std::vector<PathPoint> sample_path(double x_from_m, double x_to_m, double step_m, YOf y_of) {
  MG_DEMAND(step_m > 0.0 && x_to_m > x_from_m);
  std::vector<PathPoint> path;
  path.reserve(static_cast<std::size_t>((x_to_m - x_from_m) / step_m) + 2);
  for (int i = 0; x_from_m + i * step_m < x_to_m - 1e-3 * step_m; ++i) {
    const double x = x_from_m + i * step_m;
    path.push_back({x, y_of(x)});
  }
  path.push_back({x_to_m, y_of(x_to_m)});
  return path;
}

// A planner's command for one cycle.
struct PlanOutput {
  std::vector<PathPoint> path;          // reference path in the road frame, increasing X
  double target_speed_mps = 0.0;        // speed to track
  double accel_limit_mps2 = 0.0;        // |accel| the speed controller may use toward it
  bool proper_response = false;         // RSS proper response (spec §4): brake at least b_min
  std::vector<V2vMessage> outbox;
  // What the planner says it is doing, for reports only: a short name of its state (a change is
  // a trace event), one line of reason, and its own record (optional).
  std::string mode;
  std::string reason;
  std::shared_ptr<const PlanAnnotation> annotation;
};

// One planner cycle's account as the trace keeps it (planner_annotations.decisions[i]).
struct PlanRecord {
  double time_s = 0.0;
  std::string mode;
  std::string reason;
  std::shared_ptr<const PlanAnnotation> annotation;
};
// {"time_s", "mode", "reason", "annotation" (when there is one)}.
nlohmann::json plan_record_to_json(const PlanRecord& r);

class Planner {
 public:
  virtual ~Planner() = default;
  virtual std::string name() const = 0;
  // Called once per planner cycle. Planners may keep state between calls (commitment to a
  // merge, a pending request) but must be deterministic.
  virtual PlanOutput plan(const WorldSnapshot& world) = 0;
};

// A planner of the registry (planner/planner_registry.h): the built-ins "rcpp" (Definition 1
// only), "rcpp-coop" (Definition 1 and 2), "tripfield" (the paper's baseline), "mobil" and "frenet"
// (classic baselines, docs/baselines.md), then any registered by the
// program, or an exec planner for "exec:COMMAND" (planner/exec_planner.h). Returns nullptr for an
// unknown name. planner_names() lists the registered ones in registration order.
std::unique_ptr<Planner> make_planner(const std::string& name);
std::vector<std::string> planner_names();

// Builds the snapshot of a scenario's initial state (used by `mergeguard plan`).
WorldSnapshot initial_snapshot(const Scenario& s);

}  // namespace mg
