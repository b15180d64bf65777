// `mergeguard rss`: the spec §10 contract on stdin/stdout and exit codes.
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include "cli_runner.h"

namespace mg::test {
namespace {

const char* kStandardLongitudinal =
    R"({"rear_speed_mps":13.8889,"front_speed_mps":13.8889,"rear_length_m":0,"front_length_m":0,)"
    R"("response_time_s":2,"accel_max_mps2":2,"brake_min_mps2":4,"brake_max_mps2":8})";
const char* kStandardLateral =
    R"({"left_lat_speed_mps":0,"right_lat_speed_mps":0,"left_width_m":0,"right_width_m":0,)"
    R"("response_time_s":2,"lat_accel_max_mps2":0.2,"lat_brake_min_mps2":0.8,"fluctuation_margin_m":0.1})";

TEST(RssCommand, LongitudinalPrintsStandardRssDistance) {
  const auto r = run_cli({"rss", "longitudinal"}, kStandardLongitudinal);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out).at("distance_m").get<double>(), 59.72, 0.01);
}

TEST(RssCommand, LateralPrintsStandardRssDistance) {
  const auto r = run_cli({"rss", "lateral"}, kStandardLateral);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out).at("distance_m").get<double>(), 1.1, 1e-9);
}

TEST(RssCommand, BadInputExitsTwoWithOneLineNamingTheField) {
  struct Case {
    std::string kind, input, expected;
  };
  std::string negative = kStandardLongitudinal;
  negative.replace(negative.find("13.8889"), 7, "-3");
  std::string huge = kStandardLateral;
  huge.replace(huge.find("\"left_width_m\":0"), 16, "\"left_width_m\":1e308");
  std::string as_string = kStandardLongitudinal;
  as_string.replace(as_string.find("\"response_time_s\":2"), 19, "\"response_time_s\":\"2\"");
  const std::string unknown = std::string("{\"colour\":1,") + (kStandardLongitudinal + 1);
  const std::vector<Case> cases = {
      {"longitudinal", "", "empty input"},
      {"longitudinal", "{\"rear_speed_mps\":", "malformed JSON"},
      {"longitudinal", "\x7f\x45\x4c\x46 binary", "malformed JSON"},
      {"longitudinal", "[1,2]", "must be a JSON object"},
      {"longitudinal", negative, "/rear_speed_mps: must be in [0, 100]"},
      {"lateral", huge, "/left_width_m: must be in [0, 10]"},
      {"longitudinal", as_string, "/response_time_s: must be a number, got a string"},
      {"longitudinal", unknown, "/colour: unknown key"},
      {"lateral", R"({"left_lat_speed_mps":0})", "missing required key"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli({"rss", c.kind}, c.input);
    EXPECT_EQ(r.exit_code, 2) << c.input;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.input << " -> " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
    EXPECT_TRUE(r.out.empty()) << "nothing on stdout on error";
  }
}

TEST(RssCommand, UnknownKindIsUsageError) {
  const auto r = run_cli({"rss", "diagonal"}, kStandardLongitudinal);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("diagonal"), std::string::npos);
}

}  // namespace
}  // namespace mg::test
