// RCPP's decision record (RCPP §II; spec §5-§6): its mode, gap, v_e* interval and choice, P_c
// bounds and choice, kappa, merge duration and Definition 2 partner. RCPP's own vocabulary: it
// reaches reports as RCPP's annotation of its commands (PlanOutput::annotation), and nothing
// outside RCPP and its tests reads it typed.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/planner.h"

namespace mg {

enum class DecisionMode {
  kKeepLane,        // not merging yet / already in the main lane, following
  kDef1Merge,       // Definition 1 gap found, merging
  kDef2Request,     // Definition 2 request sent, waiting (rho_c)
  kDef2Merge,       // Definition 2 accepted, merging
  kDef1Halt,        // Definition 1.3: no gap, brake to halt before the side lane end
  kProperResponse,  // RSS override: dangerous situation, braking at least b_min
  kMerged,          // merge completed, lane keeping in the main lane
};
std::string to_string(DecisionMode m);

// A gap between main-lane vehicles: follower behind, leader ahead; -1 = open side.
struct Gap {
  int follower_id = -1;
  int leader_id = -1;
  bool operator==(const Gap&) const = default;
};

struct RcppDecision final : PlanAnnotation {
  double time_s = 0.0;
  DecisionMode mode = DecisionMode::kKeepLane;
  std::optional<Gap> gap;
  // Definition 1: feasible interval of v_e* and the choice (NaN when not applicable).
  double ve_min_mps = std::numeric_limits<double>::quiet_NaN();
  double ve_max_mps = std::numeric_limits<double>::quiet_NaN();
  double ve_star_mps = std::numeric_limits<double>::quiet_NaN();
  // Sigmoid: P_c bounds and choice, slope kappa.
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
  std::string reason;  // one human-readable line explaining the decision

  // The record's own fields (time, mode and reason are the command's: PlanRecord).
  nlohmann::json to_json() const override;
  std::vector<std::pair<std::string, std::string>> describe() const override;
};

// A command of RCPP's and the decision behind it, as RCPP's stages pass them on.
struct RcppCycle : PlanOutput {
  RcppDecision decision;
};

// The command a cycle gives: mode and reason from the decision, which becomes its annotation.
PlanOutput to_command(RcppCycle cycle);

// RCPP's decision behind a command or a trace record; nullptr when another planner made it.
const RcppDecision* rcpp_decision(const std::shared_ptr<const PlanAnnotation>& annotation);

}  // namespace mg
