// The one planner interface that the simulator, checker and fuzzer drive (issue #3 item 1).
// A planner sees a snapshot of the world and returns a reference path, a speed command,
// outgoing V2V messages and a decision record. New planners register with register_planner
// (planner/planner_registry.h), built-in or not.
#pragma once

#include <cassert>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

enum class DecisionMode {
  kKeepLane,        // not merging yet / already in the main lane, following
  kDef1Merge,       // Definition 1 gap found, merging
  kDef2Request,     // Definition 2 request sent, waiting (rho_c)
  kDef2Merge,       // Definition 2 accepted, merging
  kDef1Halt,        // Definition 1.3: no gap, brake to halt before the side lane end
  kProperResponse,  // RSS override: dangerous situation, braking at least b_min
  kMerged,          // merge completed, lane keeping in the main lane
  kPotentialField,  // baseline planner (TriPField-style), no discrete decision
};

// A gap between main-lane vehicles: follower behind, leader ahead; -1 = open side.
struct Gap {
  int follower_id = -1;
  int leader_id = -1;
  bool operator==(const Gap&) const = default;
};

// The record of one planning decision; what `mergeguard plan` prints and the trace keeps.
struct Decision {
  double time_s = 0.0;
  DecisionMode mode = DecisionMode::kKeepLane;
  std::optional<Gap> gap;
  // Definition 1: feasible interval of v_e* and the choice (NaN when not applicable).
  double ve_min_mps = std::numeric_limits<double>::quiet_NaN();
  double ve_max_mps = std::numeric_limits<double>::quiet_NaN();
  double ve_star_mps = std::numeric_limits<double>::quiet_NaN();
  // Sigmoid: P_c bounds and choice, slope kappa, lateral offset b.
  double pc_min_m = std::numeric_limits<double>::quiet_NaN();
  double pc_max_m = std::numeric_limits<double>::quiet_NaN();
  double pc_m = std::numeric_limits<double>::quiet_NaN();
  double kappa_per_m = std::numeric_limits<double>::quiet_NaN();
  // Merge duration rho the decision was evaluated with (rho_m, or longer for slow merges).
  double merge_duration_s = std::numeric_limits<double>::quiet_NaN();
  // Definition 2: responder and the v_o* asked for.
  int coop_partner_id = -1;
  double vo_star_mps = std::numeric_limits<double>::quiet_NaN();
  double d_lon_star_m = std::numeric_limits<double>::quiet_NaN();
  std::string reason;   // one human-readable line explaining the decision
  // A planner's own free-form account (an exec planner's `annotation`, docs/planner_protocol.md);
  // null when it gives none. Reports and traces show it in planner_annotations; no rule reads it.
  nlohmann::json annotation;
};

struct PathPoint {
  double x_m = 0.0;
  double y_m = 0.0;
};

// The points (x, y_of(x)) at x_from, x_from + step, ... while clearly below x_to, then x_to:
// strictly increasing X.
template <class YOf>
std::vector<PathPoint> sample_path(double x_from_m, double x_to_m, double step_m, YOf y_of) {
  assert(step_m > 0.0 && x_to_m > x_from_m);
  std::vector<PathPoint> path;
  path.reserve(static_cast<std::size_t>((x_to_m - x_from_m) / step_m) + 2);
  for (int i = 0; x_from_m + i * step_m < x_to_m - 1e-3 * step_m; ++i) {
    const double x = x_from_m + i * step_m;
    path.push_back({x, y_of(x)});
  }
  path.push_back({x_to_m, y_of(x_to_m)});
  return path;
}

struct PlanOutput {
  std::vector<PathPoint> path;          // reference path in the road frame, increasing X
  double target_speed_mps = 0.0;        // speed to track
  double accel_limit_mps2 = 0.0;        // |accel| the speed controller may use toward it
  bool proper_response = false;         // RSS override active: brake at least b_min
  std::vector<V2vMessage> outbox;
  Decision decision;
};

class Planner {
 public:
  virtual ~Planner() = default;
  virtual std::string name() const = 0;
  // Called once per planner cycle. Planners may keep state between calls (commitment to a
  // merge, a pending request) but must be deterministic.
  virtual PlanOutput plan(const WorldSnapshot& world) = 0;
};

// A planner of the registry (planner/planner_registry.h): the built-ins "rcpp" (Definition 1
// only), "rcpp-coop" (Definition 1 and 2), "tripfield" (baseline), then any registered by the
// program, or an exec planner for "exec:COMMAND" (planner/exec_planner.h). Returns nullptr for an
// unknown name. planner_names() lists the registered ones in registration order.
std::unique_ptr<Planner> make_planner(const std::string& name);
std::vector<std::string> planner_names();

std::string to_string(DecisionMode m);
nlohmann::json decision_to_json(const Decision& d);
// Builds the snapshot of a scenario's initial state (used by `mergeguard plan`).
WorldSnapshot initial_snapshot(const Scenario& s);

}  // namespace mg
