// The exec planner protocol's messages (planner/exec_protocol.h, docs/planner_protocol.md): what
// a request holds (and what it must not), and which replies are refused with what reason.
#include <string>

#include <gtest/gtest.h>

#include "core/scenario.h"
#include "planner/exec_protocol.h"
#include "tests/support/std4_scenario.h"

namespace mg {
namespace {

using nlohmann::json;

std::string refusal(const std::string& reply) {
  try {
    parse_command_reply(reply, initial_snapshot(test::std4()));
  } catch (const ProtocolError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ExecProtocol, HelloNamesTheProtocol) {
  EXPECT_EQ(json::parse(hello_request()), (json{{"type", "hello"}, {"protocol", "mergeguard-planner/1"}}));
  const PlannerIdentity id = parse_hello_reply(R"({"type":"hello","name":"p","version":"2","extra":1})");
  EXPECT_EQ(id.name, "p");
  EXPECT_EQ(id.version, "2");
  EXPECT_THROW(parse_hello_reply(R"({"type":"hello","name":"p"})"), ProtocolError);
}

TEST(ExecProtocol, ResetTellsTheRoadTheEgoAndTheParamsButNothingOfTheOthers) {
  const json reset = json::parse(reset_request(test::std4()));
  EXPECT_EQ(reset.at("type"), "reset");
  const json scenario = scenario_to_json(test::std4());
  EXPECT_EQ(reset.at("road"), scenario.at("road"));
  EXPECT_EQ(reset.at("ego"), scenario.at("ego"));
  EXPECT_EQ(reset.at("params"), scenario.at("params"));
  EXPECT_FALSE(reset.contains("vehicles"));
  EXPECT_EQ(reset.dump().find("noncompliance"), std::string::npos);
}

TEST(ExecProtocol, ObserveHoldsTheContractFields) {
  const json observe = json::parse(observe_request(initial_snapshot(test::std4())));
  EXPECT_EQ(observe.at("type"), "observe");
  EXPECT_EQ(observe.at("time_s"), 0.0);
  for (const char* key : {"x_m", "y_m", "yaw_rad", "speed_mps", "lat_speed_mps", "accel_mps2"})
    EXPECT_TRUE(observe.at("ego").contains(key)) << key;
  ASSERT_EQ(observe.at("others").size(), test::std4().vehicles.size());
  for (const char* key : {"id", "x_m", "y_m", "yaw_rad", "speed_mps", "accel_mps2", "length_m", "width_m", "limits", "v2v_capable"})
    EXPECT_TRUE(observe.at("others")[0].contains(key)) << key;
  EXPECT_EQ(observe.at("others")[0].at("limits"), limits_to_json(test::std4().vehicles[0].limits));
  EXPECT_EQ(observe.at("others")[0].at("x_m"), test::std4().vehicles[0].x_m);  // numbers read back exactly
  EXPECT_EQ(observe.at("ego").at("speed_mps"), test::std4().ego.speed_mps);
  EXPECT_TRUE(observe.at("inbox").is_array());
}

TEST(ExecProtocol, ACommandBecomesAPlanOutput) {
  const PlanOutput out = parse_command_reply(
      R"({"type":"command","path":[[0,-3.5],[50,0]],"target_speed_mps":20,"accel_limit_mps2":2,)"
      R"("outbox":[{"type":"request","to_id":1,"coop_case":"ego_behind","target_speed_mps":15}],"annotation":{"why":"gap"}})",
      initial_snapshot(test::std4()));
  ASSERT_EQ(out.path.size(), 2u);
  EXPECT_EQ(out.path[1].y_m, 0.0);
  EXPECT_EQ(out.target_speed_mps, 20.0);
  ASSERT_EQ(out.outbox.size(), 1u);
  EXPECT_EQ(out.outbox[0].to_id, 1);
  EXPECT_EQ(out.outbox[0].coop_case, CoopCase::kEgoBehind);
  ASSERT_TRUE(out.annotation);
  EXPECT_EQ(out.annotation->to_json(), (json{{"why", "gap"}}));
}

TEST(ExecProtocol, BadCommandsAreRefusedWithTheReason) {
  EXPECT_NE(refusal("not json").find("not JSON"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0],[1,0]],"target_speed_mps":NaN,"accel_limit_mps2":1})").find("not JSON"),
            std::string::npos);
  EXPECT_NE(refusal("[1,2]").find("not a JSON object"), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"ready"})").find("expected a reply of type \"command\""), std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0]],"target_speed_mps":1,"accel_limit_mps2":1})").find("at least two"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[1,0],[0,0]],"target_speed_mps":1,"accel_limit_mps2":1})").find("x does not increase"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0],[1,1e999]],"target_speed_mps":1,"accel_limit_mps2":1})"), "accepted");
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0],[1,0]],"target_speed_mps":-1,"accel_limit_mps2":1})").find(">= 0"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0],[1,0]],"accel_limit_mps2":1})").find("lacks \"target_speed_mps\""),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0],[1,0]],"target_speed_mps":1,"accel_limit_mps2":1,"outbox":[{"type":"request","to_id":99}]})")
                .find("to_id"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"command","path":[[0,0],[1,0]],"target_speed_mps":1,"accel_limit_mps2":1,"annotation":3})")
                .find("annotation"),
            std::string::npos);
}

}  // namespace
}  // namespace mg
