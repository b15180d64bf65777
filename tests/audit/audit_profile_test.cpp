// The audit profile (src/audit/audit_profile.h): documented defaults, a JSON round trip, and
// strict loading (unknown keys, wrong types, out-of-range values, a lost default class).
#include <gtest/gtest.h>

#include "audit/audit_profile.h"
#include "core/input_error.h"

namespace mg {
namespace {

std::string error_of(const nlohmann::json& j) {
  try {
    audit_profile_from_json(j, "profile.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(AuditProfile, DefaultsAreTheDocumentedOnes) {
  const AuditProfile p = default_audit_profile();
  EXPECT_DOUBLE_EQ(p.rss.response_time_s, 1.0);
  EXPECT_DOUBLE_EQ(p.limits_for("car").accel_max_mps2, 3.5);
  EXPECT_DOUBLE_EQ(p.limits_for("car").brake_min_mps2, 4.0);
  EXPECT_DOUBLE_EQ(p.limits_for("car").brake_max_mps2, 8.0);
  EXPECT_DOUBLE_EQ(p.limits_for("truck").brake_min_mps2, 3.0);
  EXPECT_DOUBLE_EQ(p.limits_for("tram").brake_min_mps2, 4.0);  // an unlisted class: "default"
  EXPECT_DOUBLE_EQ(p.rules.merge_complete_yaw_rad, 0.05);
  EXPECT_EQ(p.sensitivity.response_times_s, (std::vector<double>{0.5, 1.0, 1.5, 2.0}));
  EXPECT_EQ(p.sensitivity.brake_scales, (std::vector<double>{0.75, 1.0, 1.25}));
}

TEST(AuditProfile, RoundTripsThroughJson) {
  AuditProfile p = default_audit_profile();
  p.rss.response_time_s = 1.5;
  p.classes["car"].brake_min_mps2 = 3.0;
  p.sensitivity.brake_scales = {0.5, 1.0};
  EXPECT_EQ(audit_profile_from_json(audit_profile_to_json(p), "profile.json"), p);
}

TEST(AuditProfile, AbsentKeysKeepTheirDefaults) {
  const AuditProfile p = audit_profile_from_json({{"rss", {{"response_time_s", 2.0}}}}, "profile.json");
  EXPECT_DOUBLE_EQ(p.rss.response_time_s, 2.0);
  EXPECT_EQ(p.classes, default_audit_profile().classes);
}

TEST(AuditProfile, RefusesBadProfilesInOneLine) {
  EXPECT_EQ(error_of({{"respons_time", 1}}).rfind("profile.json: ", 0), 0u);
  EXPECT_NE(error_of({{"respons_time", 1}}).find("respons_time"), std::string::npos);
  EXPECT_NE(error_of({{"rss", {{"response_time_s", 9.0}}}}).find("/rss/response_time_s"), std::string::npos);
  EXPECT_NE(error_of({{"window_before_s", "6"}}).find("/window_before_s"), std::string::npos);
  EXPECT_NE(error_of({{"classes", {{"car", {{"brake_min_mps2", 9.0}, {"brake_max_mps2", 8.0}}}}}}).find("/classes/car"), std::string::npos);
  EXPECT_NE(error_of({{"sensitivity", {{"brake_scale", nlohmann::json::array()}}}}).find("/sensitivity/brake_scale"), std::string::npos);
  EXPECT_NE(error_of(nlohmann::json::array()).find("must be a JSON object"), std::string::npos);
}

}  // namespace
}  // namespace mg

namespace mg {
namespace {

// docs/audit_profile.default.json is the built-in profile, written out: a starting point for
// --params, kept equal to the code by this test.
TEST(AuditProfile, TheDocumentedDefaultFileIsTheBuiltInProfile) {
  EXPECT_EQ(load_audit_profile(std::string(MG_SOURCE_DIR) + "/docs/audit_profile.default.json"), default_audit_profile());
}

}  // namespace
}  // namespace mg
