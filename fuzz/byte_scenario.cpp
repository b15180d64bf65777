#include "fuzz/byte_scenario.h"

#include <algorithm>
#include <cmath>

namespace mg::fuzz {
namespace {

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  // One of n options; 0 (the simplest) once the bytes run out.
  int choice(int n) { return pos_ < size_ ? data_[pos_++] % n : 0; }

  // A grid value of the range from two bytes; the nominal value once the bytes run out.
  double real(const RealRange& r) {
    if (pos_ + 2 > size_) {
      pos_ = size_;
      return r.nominal;
    }
    const unsigned raw = static_cast<unsigned>(data_[pos_]) << 8 | data_[pos_ + 1];
    pos_ += 2;
    const auto steps = static_cast<unsigned>(std::llround((r.hi - r.lo) / r.resolution));
    return std::clamp(snap_to_grid(r.lo + (raw % (steps + 1)) * r.resolution, r.resolution), r.lo, r.hi);
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

LimitsSpec limits(ByteReader& in) {
  return {in.real(range::kAccelMax), in.real(range::kBrakeMin), in.real(range::kBrakeMaxExtra),
          in.real(range::kLatAccelMax), in.real(range::kLatBrakeMin)};
}

V2vSpec v2v(ByteReader& in, const RealRange& latency, const RealRange& loss) {
  V2vSpec v;
  v.capable = in.choice(2) == 1;
  v.latency_s = in.real(latency);
  v.loss_prob = in.real(loss);
  return v;
}

VehicleSpec vehicle(ByteReader& in) {
  VehicleSpec v;
  v.lane = in.choice(3);
  v.first_offset_m = in.real(range::kFirstOffset);
  v.gap_m = in.real(range::kGap);
  v.speed_mps = in.real(range::kSpeed);
  v.length_m = in.real(range::kLength);
  v.width_m = in.real(range::kWidth);
  v.height_m = in.real(range::kHeight);
  v.limits = limits(in);
  v.behaviour = static_cast<BehaviourType>(in.choice(6));
  v.desired_speed_delta_mps = in.real(range::kDesiredSpeedDelta);
  v.time_headway_s = in.real(range::kHeadway);
  v.min_gap_m = in.real(range::kMinGap);
  v.comfort_brake_mps2 = in.real(range::kComfortBrake);
  v.behaviour_seed = 1 + static_cast<std::uint64_t>(in.choice(256));
  v.segment_s = in.real(range::kSegment);
  v.v2v = v2v(in, range::kLatency, range::kLoss);
  v.noncompliance = static_cast<NonComplianceType>(in.choice(4));
  v.nc_start_s = in.real(range::kNcStart);
  v.nc_duration_s = in.real(range::kNcDuration);
  v.nc_excess_mps2 = in.real(range::kNcExcess);
  return v;
}

}  // namespace

ScenarioSpec spec_from_bytes(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  ScenarioSpec s;
  s.road = {in.real(range::kLaneWidth), 1 + in.choice(3), in.real(range::kSideLaneStart),
            in.real(range::kSideLaneLength), in.real(range::kSpeedLimit)};
  s.params = {in.real(range::kResponseTime), in.real(range::kMergeDuration), in.real(range::kCommThreshold),
              in.real(range::kHorizon)};
  EgoSpec& e = s.ego;
  e.offset_m = in.real(range::kEgoOffset);
  e.lateral_offset_m = in.real(range::kEgoLateralOffset);
  e.speed_mps = in.real(range::kEgoSpeed);
  e.length_m = in.real(range::kEgoLength);
  e.width_m = in.real(range::kEgoWidth);
  e.limits = limits(in);
  e.v2v = v2v(in, range::kEgoLatency, range::kEgoLoss);
  e.mass_kg = in.real(range::kMass);
  e.cg_to_front_m = in.real(range::kCgToFront);
  e.cg_to_rear_m = in.real(range::kCgToRear);
  e.cornering_front_npr = in.real(range::kCornering);
  e.cornering_rear_npr = in.real(range::kCornering);
  const int count = in.choice(kByteScenarioMaxVehicles + 1);
  for (int i = 0; i < count; ++i) s.vehicles.push_back(vehicle(in));
  return s;
}

Scenario scenario_from_bytes(const std::uint8_t* data, std::size_t size) {
  return assemble_scenario(spec_from_bytes(data, size));
}

}  // namespace mg::fuzz
