// The Definition 2 exchanges as the channel saw them (rules/coop_exchange.h): requests of the ego
// paired with their responders' answers, from channel events alone.
#include "rules/coop_exchange.h"

#include <gtest/gtest.h>

#include "rules/check.h"

namespace mg {
namespace {

ChannelEvent event(double time_s, ChannelEventKind kind, MessageType type, int from, int to) {
  ChannelEvent e;
  e.time_s = time_s;
  e.kind = kind;
  e.message.type = type;
  e.message.from_id = from;
  e.message.to_id = to;
  e.message.sent_time_s = time_s;
  return e;
}

constexpr auto kSent = ChannelEventKind::kSent;
constexpr auto kDelivered = ChannelEventKind::kDelivered;
constexpr auto kLost = ChannelEventKind::kLost;

TEST(CoopExchange, ARequestIsPairedWithItsRespondersAcceptanceSentAndDelivered) {
  ObservedTrace t;
  t.channel = {event(1.0, kSent, MessageType::kRequest, 0, 2), event(1.1, kDelivered, MessageType::kRequest, 0, 2),
               event(1.3, kSent, MessageType::kAccept, 2, 0), event(1.45, kDelivered, MessageType::kAccept, 2, 0)};
  const std::vector<CoopExchange> x = coop_exchanges(t, RuleParams{});
  ASSERT_EQ(x.size(), 1u);
  EXPECT_EQ(x[0].request->to_id, 2);
  EXPECT_EQ(x[0].request_time_s, 1.0);
  EXPECT_EQ(x[0].accept_time_s, 1.3);
  EXPECT_EQ(x[0].accept_delivered_time_s, 1.45);
  EXPECT_LT(x[0].refuse_delivered_time_s, 0.0);
}

TEST(CoopExchange, ALostAcceptanceIsSentButNeverDelivered) {
  ObservedTrace t;
  t.channel = {event(1.0, kSent, MessageType::kRequest, 0, 2), event(1.3, kSent, MessageType::kAccept, 2, 0),
               event(1.3, kLost, MessageType::kAccept, 2, 0)};
  const std::vector<CoopExchange> x = coop_exchanges(t, RuleParams{});
  ASSERT_EQ(x.size(), 1u);
  EXPECT_EQ(x[0].accept_time_s, 1.3);
  EXPECT_LT(x[0].accept_delivered_time_s, 0.0);
  EXPECT_LT(acceptance_time(t, 2, 10.0), 0.0);
}

TEST(CoopExchange, AnAnswerBelongsToTheLatestEarlierRequestToItsSender) {
  // Requests to 1 (t = 0), 2 (t = 0.5) and 1 again (t = 1): vehicle 1's refusal at 1.2 s answers
  // the second request to it; vehicle 2's acceptance answers its own; the first request to 1
  // stays unanswered.
  ObservedTrace t;
  t.channel = {event(0.0, kSent, MessageType::kRequest, 0, 1), event(0.5, kSent, MessageType::kRequest, 0, 2),
               event(1.0, kSent, MessageType::kRequest, 0, 1), event(1.1, kDelivered, MessageType::kAccept, 2, 0),
               event(1.2, kDelivered, MessageType::kRefuse, 1, 0)};
  const std::vector<CoopExchange> x = coop_exchanges(t, RuleParams{});
  ASSERT_EQ(x.size(), 3u);
  EXPECT_LT(x[0].accept_delivered_time_s, 0.0);
  EXPECT_LT(x[0].refuse_delivered_time_s, 0.0);
  EXPECT_EQ(x[1].accept_delivered_time_s, 1.1);
  EXPECT_EQ(x[2].refuse_delivered_time_s, 1.2);
  EXPECT_LT(x[2].accept_delivered_time_s, 0.0);
}

TEST(CoopExchange, MessagesBetweenOtherVehiclesAndAnswersWithoutARequestAreIgnored) {
  ObservedTrace t;
  t.channel = {event(0.0, kDelivered, MessageType::kAccept, 3, 0),  // no request to 3
               event(0.1, kSent, MessageType::kRequest, 1, 2), event(0.2, kDelivered, MessageType::kAccept, 2, 1)};
  EXPECT_TRUE(coop_exchanges(t, RuleParams{}).empty());
}

TEST(CoopExchange, AcceptanceTimeIsTheLatestDeliveryToTheEgoUpToTheGivenTime) {
  ObservedTrace t;
  t.channel = {event(0.0, kSent, MessageType::kRequest, 0, 1), event(0.3, kDelivered, MessageType::kAccept, 1, 0),
               event(2.0, kSent, MessageType::kRequest, 0, 1), event(2.4, kDelivered, MessageType::kAccept, 1, 0)};
  EXPECT_LT(acceptance_time(t, 1, 0.2), 0.0);
  EXPECT_EQ(acceptance_time(t, 1, 0.3), 0.3);
  EXPECT_EQ(acceptance_time(t, 1, 2.0), 0.3);
  EXPECT_EQ(acceptance_time(t, 1, 5.0), 2.4);
  EXPECT_LT(acceptance_time(t, 2, 5.0), 0.0);
}

// A message through the channel: its send, and its delivery or loss, the message keeping its
// send time (as the simulator records it).
ChannelEvent fate(ChannelEvent sent, double time_s, ChannelEventKind kind) {
  sent.time_s = time_s;
  sent.kind = kind;
  return sent;
}

// A re-send: the first request reached vehicle 1 at 0.1 s; vehicle 1 answered it only at
// 1.05 s (delivered 1.15 s, after t_r + rho_c = 1 s); the ego re-sent at 0.5 s. Bound to "the
// latest earlier request" the acceptance looked timely (1.15 <= 0.5 + 1); it answers the first
// request (the re-send reached vehicle 1 only at 1.1 s, after it had answered), and a re-send
// within an open window does not move t_r anyway.
TEST(CoopExchange, AReSentRequestDoesNotMakeALateAcceptanceOfTheFirstTimely) {
  const ChannelEvent first = event(0.0, kSent, MessageType::kRequest, 0, 1);
  const ChannelEvent again = event(0.5, kSent, MessageType::kRequest, 0, 1);
  const ChannelEvent accept = event(1.05, kSent, MessageType::kAccept, 1, 0);
  ObservedTrace t;
  t.channel = {first, fate(first, 0.1, kDelivered), again, accept, fate(again, 1.1, kDelivered),
               fate(accept, 1.15, kDelivered)};
  const std::vector<CoopExchange> x = coop_exchanges(t, RuleParams{});
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0].accept_delivered_time_s, 1.15);  // the first request's answer
  EXPECT_LT(x[1].accept_delivered_time_s, 0.0);
  EXPECT_EQ(x[1].request_time_s, 0.0);  // the re-send keeps the series' t_r
  EXPECT_EQ(x[1].sent_time_s, 0.5);
  EXPECT_FALSE(x[0].accepted_in_time(1.0));
  // Had vehicle 1 answered the re-send (after it reached it), the answer would still count from
  // the first request of the series: late.
  const ChannelEvent accept2 = event(1.12, kSent, MessageType::kAccept, 1, 0);
  t.channel = {first, fate(first, 0.1, kDelivered), again, fate(again, 1.1, kDelivered), accept2,
               fate(accept2, 1.2, kDelivered)};
  const std::vector<CoopExchange> y = coop_exchanges(t, RuleParams{});
  EXPECT_LT(y[0].accept_delivered_time_s, 0.0);
  EXPECT_EQ(y[1].accept_delivered_time_s, 1.2);
  EXPECT_FALSE(y[1].accepted_in_time(1.0));
}

// A series ends with an answer delivered to the ego, with its window (rho_c after its first
// request), or when every request of it was lost: the next request is a new decision, its own t_r.
TEST(CoopExchange, ASeriesEndsWithAnAnswerItsWindowOrTheLossOfAllItsRequests) {
  const auto series_starts = [](const std::vector<ChannelEvent>& channel) {
    ObservedTrace t;
    t.channel = channel;
    std::vector<double> out;
    for (const CoopExchange& x : coop_exchanges(t, RuleParams{})) out.push_back(x.request_time_s);
    return out;
  };
  const ChannelEvent r0 = event(0.0, kSent, MessageType::kRequest, 0, 1);
  const ChannelEvent r1 = event(0.6, kSent, MessageType::kRequest, 0, 1);
  const ChannelEvent r2 = event(1.3, kSent, MessageType::kRequest, 0, 1);
  EXPECT_EQ(series_starts({r0, r1, r2}), (std::vector<double>{0.0, 0.0, 1.3}));  // 1.3 > 0 + rho_c
  const ChannelEvent refusal = event(0.3, kSent, MessageType::kRefuse, 1, 0);
  EXPECT_EQ(series_starts({r0, refusal, fate(refusal, 0.4, kDelivered), r1}), (std::vector<double>{0.0, 0.6}));
  EXPECT_EQ(series_starts({r0, fate(r0, 0.0, kLost), r1}), (std::vector<double>{0.0, 0.6}));
  // A request to another vehicle is another series.
  EXPECT_EQ(series_starts({r0, event(0.2, kSent, MessageType::kRequest, 0, 2), r1}),
            (std::vector<double>{0.0, 0.2, 0.0}));
}

// The order a request claims, against the one observed at its send: the ego 6 m ahead of vehicle
// 1 (both 4.8 m long: their bodies 1.2 m apart). Alongside (3 m: the bodies overlap) either case
// fits.
TEST(CoopExchange, TheOrderMarginIsTheEgosLeadForEgoAheadAndItsLagForEgoBehind) {
  ObservedTrace t;
  t.vehicles.resize(2);
  t.vehicles[1].id = 1;
  t.steps = {ObservedStep{0.0, {ObservedState{10.0}, ObservedState{4.0}}}};
  ChannelEvent ahead = event(0.0, kSent, MessageType::kRequest, 0, 1);
  ChannelEvent behind = ahead;
  behind.message.coop_case = CoopCase::kEgoBehind;
  t.channel = {ahead, behind};
  const std::vector<CoopExchange> x = coop_exchanges(t, RuleParams{});
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0].order_margin_m, 6.0 + 4.8, 1e-12);
  EXPECT_NEAR(x[1].order_margin_m, -6.0 + 4.8, 1e-12);
  t.steps[0].vehicles[1].x_m = 7.0;
  for (const CoopExchange& y : coop_exchanges(t, RuleParams{})) EXPECT_GE(y.order_margin_m, 0.0);
}

}  // namespace
}  // namespace mg
