#include "sim/v2v_channel.h"

#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "test_planners.h"

namespace mg {
namespace {

Scenario two_capable(double ego_latency_s, double ego_loss) {
  Scenario s = test::empty_scenario();
  s.ego.v2v = {true, ego_latency_s, ego_loss};
  MainVehicle v = test::vehicle(1, 30.0, 20.0, BehaviourType::kCooperative);
  v.v2v = {true, 0.3, 0.0};
  s.vehicles.push_back(v);
  return s;
}

V2vMessage from_ego_to(int id) {
  V2vMessage m;
  m.to_id = id;
  return m;
}

std::size_t count(const std::vector<TraceEvent>& events, EventKind k) {
  return static_cast<std::size_t>(std::count_if(events.begin(), events.end(), [&](const TraceEvent& e) { return e.kind == k; }));
}

TEST(V2vChannel, DeliversAfterTheSendersLatency) {
  const Scenario s = two_capable(0.25, 0.0);
  V2vChannel channel(s);
  std::vector<TraceEvent> events;
  channel.send(from_ego_to(1), 1.0, events);
  EXPECT_TRUE(channel.deliver_due(1.24, events).empty());
  const auto due = channel.deliver_due(1.25, events);
  ASSERT_EQ(due.size(), 1u);
  EXPECT_EQ(due[0].to_id, 1);
  EXPECT_TRUE(channel.deliver_due(5.0, events).empty()) << "delivered once";
  EXPECT_EQ(count(events, EventKind::kMessageSent), 1u);
  EXPECT_EQ(count(events, EventKind::kMessageDelivered), 1u);
}

TEST(V2vChannel, LossProbabilityOneDropsEveryMessageAndZeroNone) {
  for (double loss : {0.0, 1.0}) {
    const Scenario s = two_capable(0.1, loss);
    V2vChannel channel(s);
    std::vector<TraceEvent> events;
    for (int i = 0; i < 50; ++i) channel.send(from_ego_to(1), 0.1 * i, events);
    EXPECT_EQ(channel.deliver_due(100.0, events).size(), loss == 0.0 ? 50u : 0u);
    EXPECT_EQ(count(events, EventKind::kMessageLost), loss == 0.0 ? 0u : 50u);
  }
}

TEST(V2vChannel, PartialLossIsSeededAndRepeatable) {
  const Scenario s = two_capable(0.1, 0.5);
  auto delivered = [&] {
    V2vChannel channel(s);
    std::vector<TraceEvent> events;
    for (int i = 0; i < 200; ++i) channel.send(from_ego_to(1), 0.01 * i, events);
    return channel.deliver_due(100.0, events).size();
  };
  const std::size_t n = delivered();
  EXPECT_EQ(n, delivered());
  EXPECT_GT(n, 60u);
  EXPECT_LT(n, 140u);
}

// Losses follow the sender's declared rate: over 2000 messages the count lost is within five
// standard deviations of the binomial mean, whatever the rate and the scenario's seeds.
RC_GTEST_PROP(V2vChannel, LossesFollowTheDeclaredRate, ()) {
  const double loss = *rc::gen::inRange(0, 101) / 100.0;
  Scenario s = two_capable(0.1, loss);
  s.vehicles[0].behaviour.seed = *rc::gen::arbitrary<std::uint64_t>();
  V2vChannel channel(s);
  std::vector<TraceEvent> events;
  constexpr int kMessages = 2000;
  for (int i = 0; i < kMessages; ++i) channel.send(from_ego_to(1), 0.01 * i, events);
  const double lost = static_cast<double>(count(events, EventKind::kMessageLost));
  const double mean = kMessages * loss;
  const double sd = std::sqrt(kMessages * loss * (1.0 - loss));
  RC_ASSERT(std::abs(lost - mean) <= 5.0 * sd + 1.0);
  RC_ASSERT(lost + static_cast<double>(channel.deliver_due(100.0, events).size()) == kMessages);
}

TEST(V2vChannel, MessagesToOrFromVehiclesWithoutV2vAreLost) {
  Scenario s = two_capable(0.1, 0.0);
  s.vehicles[0].v2v.capable = false;
  V2vChannel channel(s);
  std::vector<TraceEvent> events;
  channel.send(from_ego_to(1), 0.0, events);
  channel.send(from_ego_to(99), 0.0, events);
  EXPECT_TRUE(channel.deliver_due(10.0, events).empty());
  EXPECT_EQ(count(events, EventKind::kMessageLost), 2u);
}

}  // namespace
}  // namespace mg
