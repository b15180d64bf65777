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
  const std::vector<CoopExchange> x = coop_exchanges(t);
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
  const std::vector<CoopExchange> x = coop_exchanges(t);
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
  const std::vector<CoopExchange> x = coop_exchanges(t);
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
  EXPECT_TRUE(coop_exchanges(t).empty());
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

}  // namespace
}  // namespace mg
