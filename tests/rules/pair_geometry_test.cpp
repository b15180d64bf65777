// PairStepper (rules/pair_geometry.h) streams the pair geometry step by step with a per-pair
// memo of the RSS distances; the monitors rely on it giving exactly what pair_geometry() gives.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cstdint>

#include "rules/pair_geometry.h"
#include "trace_builder.h"

namespace mg::test {
namespace {

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

void expect_same_bits(const PairGeometry& a, const PairGeometry& b) {
  EXPECT_EQ(a.rear, b.rear);
  EXPECT_EQ(a.front, b.front);
  EXPECT_EQ(a.left, b.left);
  EXPECT_EQ(a.right, b.right);
  EXPECT_EQ(bits(a.gap_m), bits(b.gap_m));
  EXPECT_EQ(bits(a.d_lon_m), bits(b.d_lon_m));
  EXPECT_EQ(bits(a.dy_m), bits(b.dy_m));
  EXPECT_EQ(bits(a.d_lat_m), bits(b.d_lat_m));
}

RC_GTEST_PROP(PairStepper, StreamedGeometryEqualsFreshGeometryBitForBit, ()) {
  Scenario s = base_scenario();
  s.road.main_lanes = 2;
  const int vehicles = *rc::gen::inRange(1, 7);
  std::vector<double> accel{*rc::gen::element(-3.0, 0.0, 1.5)};
  for (int k = 0; k < vehicles; ++k) {
    MainVehicle v = vehicle(k + 1, -60.0 + 25.0 * k, *rc::gen::inRange(0, 30));
    v.lane = k % 2;
    s.vehicles.push_back(v);
    accel.push_back(*rc::gen::element(-4.0, 0.0, 0.0, 2.0));  // constant speeds exercise the memo
  }
  Trace t = constant_accel_trace(s, 3.0, accel);
  const double vy = *rc::gen::element(0.0, 0.4);
  for (std::size_t k = 0; k < t.steps.size(); ++k) {  // the ego drifts left at times: D_lat changes
    t.steps[k].ego.vy_mps = k % 40 < 20 ? vy : 0.0;
    t.steps[k].ego.y_m += 0.02 * static_cast<double>(k) * vy;
  }
  const ObservedTrace o = observed(s, t);
  PairStepper stepper(o);
  const std::size_t n = stepper.vehicles();
  RC_ASSERT(n == static_cast<std::size_t>(vehicles) + 1);
  for (const ObservedStep& st : o.steps) {
    stepper.load(st);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) expect_same_bits(stepper.at(PairStepper::index(n, i, j), i, j), pair_geometry(o, st, i, j));
  }
}

TEST(PairStepper, PairIndicesEnumerateThePairsInOrder) {
  const std::size_t n = 6;
  std::size_t expected = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) EXPECT_EQ(PairStepper::index(n, i, j), expected++);
  EXPECT_EQ(expected, n * (n - 1) / 2);
}

}  // namespace
}  // namespace mg::test
