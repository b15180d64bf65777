#include "fuzz/scenario_families.h"

#include <algorithm>

#include "fuzz/choice_gen.h"

namespace mg::fuzz {
namespace {

// A V2V link: latency over its whole range, and a lossy link on one draw in four (a lost request
// or answer is what Def. 2.3's fallback is for; mostly lossless so that the exchange happens).
rc::Gen<V2vSpec> gen_link(const RealRange& latency) {
  const auto loss = rc::gen::mapcat(gen_choice<bool>({{3, false}, {1, true}}), [](bool lossy) {
    return lossy ? gen_real(range::kCoopLoss) : rc::gen::just(0.0);
  });
  return rc::gen::apply([](double latency_s, double loss_prob) { return V2vSpec{true, latency_s, loss_prob}; },
                        gen_real(latency), loss);
}

// The partner's answer to a request, and the acts of a non-compliant one (reneging accepts from
// t = 0; over-braking is a burst beyond b_max while the exchange or the merge is under way).
VehicleSpec as_partner(VehicleSpec v, PartnerKind kind, double overbrake_start_s, double overbrake_duration_s) {
  v.behaviour = kind == PartnerKind::kNonResponsive ? BehaviourType::kNonResponsive : BehaviourType::kCooperative;
  v.noncompliance = NonComplianceType::kNone;
  if (kind == PartnerKind::kReneging) {
    v.noncompliance = NonComplianceType::kRenege;
    v.nc_start_s = 0.0;
    v.nc_duration_s = range::kNcDuration.hi;
  } else if (kind == PartnerKind::kOverbraking) {
    v.noncompliance = NonComplianceType::kExceedBrake;
    v.nc_start_s = overbrake_start_s;
    v.nc_duration_s = overbrake_duration_s;
  }
  return v;
}

rc::Gen<std::vector<VehicleSpec>> gen_others(const GenConfig& config, int at_most) {
  const int n = std::clamp(at_most, 0, std::max(0, config.max_vehicles));
  return rc::gen::resize(n, rc::gen::container<std::vector<VehicleSpec>>(gen_vehicle(config)));
}

// Where a family puts the target lane's rearmost vehicle relative to the ego, and whether it is
// a V2V partner with the exchange's parameters drawn where Definition 2 can apply.
struct Shape {
  RealRange offset;
  RealRange speed_delta;
  bool v2v_partner = true;
};

struct PartnerDraw {
  VehicleSpec vehicle;
  PartnerKind kind = PartnerKind::kCooperative;
  double offset_m = 0.0;
  double speed_delta_mps = 0.0;
  double overbrake_start_s = 0.0;
  double overbrake_duration_s = 0.0;
  V2vSpec link;
};

rc::Gen<PartnerDraw> gen_partner_draw(const GenConfig& config, const Shape& shape) {
  return rc::gen::build<PartnerDraw>(
      rc::gen::set(&PartnerDraw::vehicle, gen_vehicle(config)),
      rc::gen::set(&PartnerDraw::kind, gen_partner_kind(config)),
      rc::gen::set(&PartnerDraw::offset_m, gen_real(shape.offset)),
      rc::gen::set(&PartnerDraw::speed_delta_mps, gen_real(shape.speed_delta)),
      rc::gen::set(&PartnerDraw::overbrake_start_s, gen_real(range::kOverbrakeStart)),
      rc::gen::set(&PartnerDraw::overbrake_duration_s, gen_real(range::kOverbrakeDuration)),
      rc::gen::set(&PartnerDraw::link, gen_link(range::kCoopLatency)));
}

// The chosen vehicle is the first (rearmost) of the target lane, at the drawn offset from the
// ego and near its speed; the other vehicles are uniform (in the target lane they are placed
// ahead of it, RSS-safe). A V2V partner's family also draws the ego's link, rho_m and rho_c.
rc::Gen<ScenarioSpec> gen_shaped_spec(const GenConfig& config, const Shape& shape) {
  const bool v2v = shape.v2v_partner;
  return rc::gen::apply(
      [v2v](ScenarioSpec spec, PartnerDraw draw, double ego_speed_mps, V2vSpec ego_link, double merge_duration_s,
            double comm_threshold_s, double horizon_s) {
        spec.ego.speed_mps = ego_speed_mps;
        VehicleSpec first = draw.vehicle;
        if (v2v) {
          spec.ego.v2v = ego_link;
          first = as_partner(first, draw.kind, draw.overbrake_start_s, draw.overbrake_duration_s);
          first.v2v = draw.link;
          spec.params.merge_duration_s = merge_duration_s;
          spec.params.comm_threshold_s = comm_threshold_s;
        }
        first.lane = 0;
        first.first_offset_m = draw.offset_m;
        first.speed_mps = std::clamp(ego_speed_mps + draw.speed_delta_mps, 0.0, range::kSpeed.hi);
        spec.vehicles.insert(spec.vehicles.begin(), first);
        spec.params.horizon_s = horizon_s;
        return spec;
      },
      rc::gen::build<ScenarioSpec>(rc::gen::set(&ScenarioSpec::road, gen_road()),
                                   rc::gen::set(&ScenarioSpec::ego, gen_ego()),
                                   rc::gen::set(&ScenarioSpec::vehicles, gen_others(config, std::min(3, config.max_vehicles - 1))),
                                   rc::gen::set(&ScenarioSpec::params, gen_params())),
      gen_partner_draw(config, shape), gen_real(range::kCoopEgoSpeed), gen_link(range::kEgoLatency),
      gen_real(range::kCoopMergeDuration), gen_real(range::kCoopCommThreshold), gen_real(range::kFamilyHorizon));
}

}  // namespace

std::string to_string(ScenarioFamily f) {
  switch (f) {
    case ScenarioFamily::kUniform: return "uniform";
    case ScenarioFamily::kCoopBehind: return "coop_partner_behind";
    case ScenarioFamily::kCoopAhead: return "coop_partner_ahead";
    case ScenarioFamily::kFollowerBehind: return "follower_behind";
  }
  return "unknown";
}

std::vector<std::pair<std::uint64_t, ScenarioFamily>> family_weights(const GenConfig& config) {
  if (!config.targeted_families || config.max_vehicles < 1) return {{1, ScenarioFamily::kUniform}};
  // A third uniform; Def. 2.2 applies in fewer of its family's scenarios than Def. 2.1 in its
  // own, hence twice the weight; the follower family keeps Def. 1.1's and the P_c rule's shares
  // (docs/fuzzing.md "Scenario families").
  return {{3, ScenarioFamily::kUniform},
          {2, ScenarioFamily::kCoopBehind},
          {5, ScenarioFamily::kCoopAhead},
          {2, ScenarioFamily::kFollowerBehind}};
}

rc::Gen<ScenarioFamily> gen_family(const GenConfig& config) { return gen_choice<ScenarioFamily>(family_weights(config)); }

rc::Gen<PartnerKind> gen_partner_kind(const GenConfig& config) {
  if (!config.allow_noncompliance)
    return gen_choice<PartnerKind>({{4, PartnerKind::kCooperative}, {1, PartnerKind::kNonResponsive}});
  return gen_choice<PartnerKind>({{4, PartnerKind::kCooperative},
                                  {1, PartnerKind::kNonResponsive},
                                  {1, PartnerKind::kReneging},
                                  {1, PartnerKind::kOverbraking}});
}

rc::Gen<ScenarioSpec> gen_family_spec(ScenarioFamily family, const GenConfig& config) {
  switch (family) {
    case ScenarioFamily::kUniform: return gen_uniform_spec(config);
    case ScenarioFamily::kCoopBehind:
      return gen_shaped_spec(config, {range::kCoopBehindOffset, range::kCoopSpeedDelta, true});
    case ScenarioFamily::kCoopAhead:
      return gen_shaped_spec(config, {range::kCoopAheadOffset, range::kCoopAheadSpeedDelta, true});
    case ScenarioFamily::kFollowerBehind:
      return gen_shaped_spec(config, {range::kFollowerOffset, range::kCoopSpeedDelta, false});
  }
  return gen_uniform_spec(config);
}

}  // namespace mg::fuzz
