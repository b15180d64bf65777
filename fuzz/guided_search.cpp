#include "fuzz/guided_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numbers>

#include "fuzz/scenario_gen.h"

namespace mg::fuzz {
namespace {

// A scalar of a ScenarioSpec that guided search may move, and the generator's range for it
// (scenario_spec.h). `field` returns nullptr when the vehicle does not exist.
struct KnobDef {
  const char* name;
  RealRange range;
  double* (*field)(ScenarioSpec&, std::size_t vehicle);
};

double* vehicle_field(ScenarioSpec& s, std::size_t v, double VehicleSpec::*member) {
  return v < s.vehicles.size() ? &(s.vehicles[v].*member) : nullptr;
}
double* vehicle_limit(ScenarioSpec& s, std::size_t v, double LimitsSpec::*member) {
  return v < s.vehicles.size() ? &(s.vehicles[v].limits.*member) : nullptr;
}

// Global knobs first, then per-vehicle knobs (from kFirstVehicleKnob on).
const std::array<KnobDef, 26> kKnobs = {{
    {"ego.offset_m", range::kEgoOffset, [](ScenarioSpec& s, std::size_t) { return &s.ego.offset_m; }},
    {"ego.lateral_offset_m", range::kEgoLateralOffset, [](ScenarioSpec& s, std::size_t) { return &s.ego.lateral_offset_m; }},
    {"ego.speed_mps", range::kEgoSpeed, [](ScenarioSpec& s, std::size_t) { return &s.ego.speed_mps; }},
    {"ego.accel_max_mps2", range::kAccelMax, [](ScenarioSpec& s, std::size_t) { return &s.ego.limits.accel_max_mps2; }},
    {"ego.brake_min_mps2", range::kBrakeMin, [](ScenarioSpec& s, std::size_t) { return &s.ego.limits.brake_min_mps2; }},
    {"ego.brake_max_extra_mps2", range::kBrakeMaxExtra,
     [](ScenarioSpec& s, std::size_t) { return &s.ego.limits.brake_max_extra_mps2; }},
    {"ego.v2v.latency_s", range::kEgoLatency, [](ScenarioSpec& s, std::size_t) { return &s.ego.v2v.latency_s; }},
    {"road.side_lane_length_m", range::kSideLaneLength, [](ScenarioSpec& s, std::size_t) { return &s.road.side_lane_length_m; }},
    {"params.response_time_s", range::kResponseTime, [](ScenarioSpec& s, std::size_t) { return &s.params.response_time_s; }},
    {"params.merge_duration_s", range::kMergeDuration, [](ScenarioSpec& s, std::size_t) { return &s.params.merge_duration_s; }},
    {"params.comm_threshold_s", range::kCommThreshold, [](ScenarioSpec& s, std::size_t) { return &s.params.comm_threshold_s; }},
    {"params.horizon_s", range::kHorizon, [](ScenarioSpec& s, std::size_t) { return &s.params.horizon_s; }},
    {"vehicle.first_offset_m", range::kFirstOffset, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::first_offset_m); }},
    {"vehicle.gap_m", range::kGap, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::gap_m); }},
    {"vehicle.speed_mps", range::kSpeed, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::speed_mps); }},
    {"vehicle.desired_speed_delta_mps", range::kDesiredSpeedDelta,
     [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::desired_speed_delta_mps); }},
    {"vehicle.accel_max_mps2", range::kAccelMax, [](ScenarioSpec& s, std::size_t v) { return vehicle_limit(s, v, &LimitsSpec::accel_max_mps2); }},
    {"vehicle.brake_min_mps2", range::kBrakeMin, [](ScenarioSpec& s, std::size_t v) { return vehicle_limit(s, v, &LimitsSpec::brake_min_mps2); }},
    {"vehicle.brake_max_extra_mps2", range::kBrakeMaxExtra,
     [](ScenarioSpec& s, std::size_t v) { return vehicle_limit(s, v, &LimitsSpec::brake_max_extra_mps2); }},
    {"vehicle.v2v.latency_s", range::kLatency,
     [](ScenarioSpec& s, std::size_t v) { return v < s.vehicles.size() ? &s.vehicles[v].v2v.latency_s : nullptr; }},
    {"vehicle.time_headway_s", range::kHeadway, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::time_headway_s); }},
    {"vehicle.comfort_brake_mps2", range::kComfortBrake,
     [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::comfort_brake_mps2); }},
    {"vehicle.segment_s", range::kSegment, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::segment_s); }},
    {"vehicle.nc_start_s", range::kNcStart, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::nc_start_s); }},
    {"vehicle.nc_duration_s", range::kNcDuration, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::nc_duration_s); }},
    {"vehicle.nc_excess_mps2", range::kNcExcess, [](ScenarioSpec& s, std::size_t v) { return vehicle_field(s, v, &VehicleSpec::nc_excess_mps2); }},
}};
constexpr int kFirstVehicleKnob = 12;
constexpr std::array<double, 3> kStepScales = {0.01, 0.03, 0.1};  // of the knob's range

// The top 53 bits of a random word as a double in [0, 1).
double unit_interval(std::uint64_t word) { return static_cast<double>(word >> 11) * 0x1.0p-53; }
double uniform01(rc::Random& random) { return unit_interval(random.next()); }

// Box-Muller: one standard normal draw.
double standard_normal(rc::Random& random) {
  const double u1 = std::max(uniform01(random), 1e-300);
  const double u2 = uniform01(random);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace

std::string to_string(SearchMode mode) { return mode == SearchMode::kGuided ? "guided" : "random"; }

std::optional<SearchMode> search_mode_from_string(const std::string& text) {
  if (text == "random") return SearchMode::kRandom;
  if (text == "guided") return SearchMode::kGuided;
  return std::nullopt;
}

bool is_guided_run(std::uint64_t campaign_seed, std::uint64_t run_index, std::uint64_t shard_run,
                   const GuidedParams& params) {
  if (shard_run / params.batch_runs < params.lag_batches) return false;
  const std::uint64_t h = run_seed(campaign_seed ^ 0x6775696465645f31ULL, run_index);  // "guided_1"
  return unit_interval(h) < params.guided_share;
}

std::vector<KnobInfo> knobs() {
  std::vector<KnobInfo> out;
  for (std::size_t k = 0; k < kKnobs.size(); ++k)
    out.push_back({kKnobs[k].name, kKnobs[k].range, static_cast<int>(k) >= kFirstVehicleKnob});
  return out;
}

std::optional<double> knob_value(const ScenarioSpec& spec, int knob, std::size_t vehicle) {
  ScenarioSpec copy = spec;  // the table's accessors are for writing
  const double* value = kKnobs.at(static_cast<std::size_t>(knob)).field(copy, vehicle);
  return value ? std::optional<double>(*value) : std::nullopt;
}

Perturbation draw_perturbation(const ScenarioSpec& parent, rc::Random random) {
  const std::size_t vehicles = parent.vehicles.size();
  const std::size_t per_vehicle = kKnobs.size() - kFirstVehicleKnob;
  const std::size_t choices = kFirstVehicleKnob + per_vehicle * vehicles;
  const std::uint64_t count = 1 + random.next() % 3;
  Perturbation steps;
  for (std::uint64_t n = 0; n < count; ++n) {
    const std::size_t c = random.next() % choices;
    KnobStep step;
    if (c < kFirstVehicleKnob) {
      step.knob = static_cast<int>(c);
    } else {
      step.knob = kFirstVehicleKnob + static_cast<int>((c - kFirstVehicleKnob) % per_vehicle);
      step.vehicle = (c - kFirstVehicleKnob) / per_vehicle;
    }
    const RealRange& r = kKnobs[static_cast<std::size_t>(step.knob)].range;
    const double scale = kStepScales[random.next() % kStepScales.size()];
    step.delta = standard_normal(random) * scale * (r.hi - r.lo);
    // At least one grid step, so that a draw never leaves the scalar where it was.
    if (std::abs(step.delta) < r.resolution) step.delta = std::copysign(r.resolution, step.delta);
    steps.push_back(step);
  }
  return steps;
}

ScenarioSpec apply_perturbation(ScenarioSpec spec, const Perturbation& steps) {
  for (const KnobStep& step : steps) {
    const KnobDef& k = kKnobs.at(static_cast<std::size_t>(step.knob));
    double* value = k.field(spec, step.vehicle);
    if (value == nullptr) continue;
    *value = std::clamp(snap_to_grid(*value + step.delta, k.range.resolution), k.range.lo, k.range.hi);
  }
  return spec;
}

void ElitePool::offer(const std::string& rule, const Elite& elite) {
  std::vector<Elite>& elites = by_rule_[rule];
  const auto before = [](const Elite& a, const Elite& b) { return a.margin != b.margin ? a.margin < b.margin : a.run < b.run; };
  elites.insert(std::upper_bound(elites.begin(), elites.end(), elite, before), elite);
  if (elites.size() > pool_size_) elites.pop_back();
}

const Elite& ElitePool::pick(rc::Random& random) const {
  auto rule = by_rule_.begin();
  std::advance(rule, static_cast<std::ptrdiff_t>(random.next() % by_rule_.size()));
  return rule->second[random.next() % rule->second.size()];
}

PoolHistory::PoolHistory(const GuidedParams& params) : params_(params) {
  pools_[0] = std::make_shared<const ElitePool>(params_.pool_size);
}

void PoolHistory::complete(std::uint64_t shard_run, Offers offers) {
  std::lock_guard lock(mutex_);
  auto& [done, batch_offers] = pending_[shard_run / params_.batch_runs];
  ++done;
  std::move(offers.begin(), offers.end(), std::back_inserter(batch_offers));
  bool committed = false;
  for (auto it = pending_.find(committed_batches_); it != pending_.end() && it->second.first == params_.batch_runs;
       it = pending_.find(committed_batches_)) {
    auto pool = std::make_shared<ElitePool>(*pools_.at(committed_batches_));
    for (const auto& [rule, elite] : it->second.second) pool->offer(rule, elite);
    pending_.erase(it);
    pools_[++committed_batches_] = std::move(pool);
    committed = true;
  }
  while (pools_.begin()->first + params_.lag_batches + 1 < committed_batches_) pools_.erase(pools_.begin());
  if (committed) changed_.notify_all();
}

std::shared_ptr<const ElitePool> PoolHistory::pool_for(std::uint64_t shard_run, const std::function<bool()>& abandon) {
  const std::uint64_t batch = shard_run / params_.batch_runs;
  if (batch < params_.lag_batches) return std::make_shared<const ElitePool>(params_.pool_size);  // warm-up
  const std::uint64_t level = batch - params_.lag_batches + 1;
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return committed_batches_ >= level || abandon(); });
  if (committed_batches_ < level) return nullptr;
  return pools_.at(level);
}

void PoolHistory::wake() {
  std::lock_guard lock(mutex_);
  changed_.notify_all();
}

}  // namespace mg::fuzz
