#include "fuzz/scenario_gen.h"

#include <algorithm>

#include "fuzz/choice_gen.h"
#include "fuzz/scenario_families.h"

namespace mg::fuzz {
namespace {

using rc::gen::build;
using rc::gen::set;

rc::Gen<bool> gen_bool(std::uint64_t weight_false, std::uint64_t weight_true) {
  return gen_choice<bool>({{weight_false, false}, {weight_true, true}});
}

rc::Gen<V2vSpec> gen_v2v(const RealRange& latency, const RealRange& loss) {
  return build<V2vSpec>(set(&V2vSpec::capable, gen_bool(1, 1)), set(&V2vSpec::latency_s, gen_real(latency)),
                        set(&V2vSpec::loss_prob, gen_real(loss)));
}

rc::Gen<NonComplianceType> gen_noncompliance(const GenConfig& config) {
  if (!config.allow_noncompliance) return gen_choice<NonComplianceType>({{1, NonComplianceType::kNone}});
  return gen_choice<NonComplianceType>({{7, NonComplianceType::kNone},
                                        {1, NonComplianceType::kExceedAccel},
                                        {1, NonComplianceType::kExceedBrake},
                                        {1, NonComplianceType::kRenege}});
}

}  // namespace

rc::Gen<RoadSpec> gen_road() {
  return build<RoadSpec>(set(&RoadSpec::lane_width_m, gen_real(range::kLaneWidth)),
                         set(&RoadSpec::main_lanes, gen_choice<int>({{6, 1}, {3, 2}, {1, 3}})),
                         set(&RoadSpec::side_lane_start_x_m, gen_real(range::kSideLaneStart)),
                         set(&RoadSpec::side_lane_length_m, gen_real(range::kSideLaneLength)),
                         set(&RoadSpec::speed_limit_mps, gen_real(range::kSpeedLimit)));
}

rc::Gen<EgoSpec> gen_ego() {
  return build<EgoSpec>(set(&EgoSpec::offset_m, gen_real(range::kEgoOffset)),
                        set(&EgoSpec::lateral_offset_m, gen_real(range::kEgoLateralOffset)),
                        set(&EgoSpec::speed_mps, gen_real(range::kEgoSpeed)),
                        set(&EgoSpec::length_m, gen_real(range::kEgoLength)),
                        set(&EgoSpec::width_m, gen_real(range::kEgoWidth)), set(&EgoSpec::limits, gen_limits()),
                        set(&EgoSpec::v2v, gen_v2v(range::kEgoLatency, range::kEgoLoss)),
                        set(&EgoSpec::mass_kg, gen_real(range::kMass)),
                        set(&EgoSpec::cg_to_front_m, gen_real(range::kCgToFront)),
                        set(&EgoSpec::cg_to_rear_m, gen_real(range::kCgToRear)),
                        set(&EgoSpec::cornering_front_npr, gen_real(range::kCornering)),
                        set(&EgoSpec::cornering_rear_npr, gen_real(range::kCornering)));
}

rc::Gen<ParamsSpec> gen_params() {
  return build<ParamsSpec>(set(&ParamsSpec::response_time_s, gen_real(range::kResponseTime)),
                           set(&ParamsSpec::merge_duration_s, gen_real(range::kMergeDuration)),
                           set(&ParamsSpec::comm_threshold_s, gen_real(range::kCommThreshold)),
                           set(&ParamsSpec::horizon_s, gen_real(range::kHorizon)));
}

rc::Gen<LimitsSpec> gen_limits() {
  return build<LimitsSpec>(set(&LimitsSpec::accel_max_mps2, gen_real(range::kAccelMax)),
                           set(&LimitsSpec::brake_min_mps2, gen_real(range::kBrakeMin)),
                           set(&LimitsSpec::brake_max_extra_mps2, gen_real(range::kBrakeMaxExtra)),
                           set(&LimitsSpec::lat_accel_max_mps2, gen_real(range::kLatAccelMax)),
                           set(&LimitsSpec::lat_brake_min_mps2, gen_real(range::kLatBrakeMin)));
}

rc::Gen<VehicleSpec> gen_vehicle(const GenConfig& config) {
  // Simplest behaviour first: shrinking walks toward constant speed.
  const auto behaviour = gen_choice<BehaviourType>({{2, BehaviourType::kConstantSpeed},
                                                    {3, BehaviourType::kIdm},
                                                    {2, BehaviourType::kRssFollower},
                                                    {2, BehaviourType::kBoundedRandom},
                                                    {2, BehaviourType::kCooperative},
                                                    {1, BehaviourType::kNonResponsive}});
  return build<VehicleSpec>(
      set(&VehicleSpec::lane, gen_choice<int>({{6, 0}, {3, 1}, {1, 2}})),
      set(&VehicleSpec::first_offset_m, gen_real(range::kFirstOffset)), set(&VehicleSpec::gap_m, gen_real(range::kGap)),
      set(&VehicleSpec::speed_mps, gen_real(range::kSpeed)), set(&VehicleSpec::length_m, gen_real(range::kLength)),
      set(&VehicleSpec::width_m, gen_real(range::kWidth)), set(&VehicleSpec::height_m, gen_real(range::kHeight)),
      set(&VehicleSpec::limits, gen_limits()), set(&VehicleSpec::behaviour, behaviour),
      set(&VehicleSpec::desired_speed_delta_mps, gen_real(range::kDesiredSpeedDelta)),
      set(&VehicleSpec::time_headway_s, gen_real(range::kHeadway)),
      set(&VehicleSpec::min_gap_m, gen_real(range::kMinGap)),
      set(&VehicleSpec::comfort_brake_mps2, gen_real(range::kComfortBrake)),
      set(&VehicleSpec::behaviour_seed, gen_uint(1, range::kBehaviourSeedMax)),
      set(&VehicleSpec::segment_s, gen_real(range::kSegment)),
      set(&VehicleSpec::v2v, gen_v2v(range::kLatency, range::kLoss)),
      set(&VehicleSpec::noncompliance, gen_noncompliance(config)),
      set(&VehicleSpec::nc_start_s, gen_real(range::kNcStart)),
      set(&VehicleSpec::nc_duration_s, gen_real(range::kNcDuration)),
      set(&VehicleSpec::nc_excess_mps2, gen_real(range::kNcExcess)));
}

rc::Gen<ScenarioSpec> gen_uniform_spec(const GenConfig& config) {
  const int max_vehicles = std::clamp(config.max_vehicles, 0, static_cast<int>(kMaxVehicles));
  // Count uniform in [0, max_vehicles]; shrinking removes vehicles first.
  auto vehicles = rc::gen::resize(max_vehicles, rc::gen::container<std::vector<VehicleSpec>>(gen_vehicle(config)));
  return build<ScenarioSpec>(set(&ScenarioSpec::road, gen_road()), set(&ScenarioSpec::ego, gen_ego()),
                             set(&ScenarioSpec::vehicles, std::move(vehicles)),
                             set(&ScenarioSpec::params, gen_params()));
}

rc::Gen<ScenarioSpec> gen_scenario_spec(const GenConfig& config) {
  // Only uniform: exactly the scenarios of the generator before the families (same random draws).
  if (family_weights(config).size() == 1) return gen_uniform_spec(config);
  const auto family = gen_family(config);
  return rc::gen::mapcat(family, [config](ScenarioFamily f) { return gen_family_spec(f, config); });
}

rc::Gen<Scenario> gen_scenario(const GenConfig& config) {
  return rc::gen::map(gen_scenario_spec(config), assemble_scenario);
}

std::uint64_t run_seed(std::uint64_t campaign_seed, std::uint64_t run_index) {
  // splitmix64 finaliser over both inputs (Steele et al. 2014).
  auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  return mix(mix(campaign_seed) ^ run_index);
}

rc::Shrinkable<Scenario> generate_scenario(std::uint64_t seed, const GenConfig& config) {
  return gen_scenario(config)(rc::Random(seed), rc::kNominalSize);
}

rc::Shrinkable<ScenarioSpec> generate_spec(std::uint64_t seed, const GenConfig& config) {
  return gen_scenario_spec(config)(rc::Random(seed), rc::kNominalSize);
}

}  // namespace mg::fuzz
