#include "audit/audit_profile.h"

#include "core/input_error.h"
#include "core/json_reader.h"

namespace mg {
namespace {

// Limits of recorded drivers are unknown: these are common RSS assumptions for human drivers
// (docs/audit.md gives sources and the ranges the sensitivity sweep covers).
std::map<std::string, Limits> default_classes() {
  return {
      {"car", Limits{3.5, 4.0, 8.0, 0.2, 0.8}},
      {"truck", Limits{1.5, 3.0, 6.0, 0.2, 0.8}},
      {"bus", Limits{1.5, 3.0, 6.0, 0.2, 0.8}},
      {"motorcycle", Limits{4.0, 4.0, 8.0, 0.2, 0.8}},
      {"default", Limits{3.5, 4.0, 8.0, 0.2, 0.8}},
  };
}

std::vector<double> number_list(const ObjectReader& r, std::string_view key, double lo, double hi) {
  const nlohmann::json& a = r.array(key);
  if (!a.is_array() || a.empty() || a.size() > 16) r.fail(key, "must be an array of 1 to 16 numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string p = r.path_of(key) + "/" + std::to_string(i);
    if (!a[i].is_number()) throw InputError(r.source(), p, "must be a number");
    const double v = a[i].get<double>();
    if (!(v >= lo && v <= hi)) throw InputError(r.source(), p, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    out.push_back(v);
  }
  return out;
}

void read_classes(const ObjectReader& r, AuditProfile& p) {
  const ObjectReader c = r.object("classes");
  for (const auto& [type, limits] : c.value().items()) {
    p.classes[type] = limits_from_json(limits, r.source(), c.path_of(type));
  }
}

void read_sensitivity(const ObjectReader& r, AuditProfile& p) {
  const ObjectReader s = r.object("sensitivity");
  s.only_keys({"response_time_s", "brake_scale"});
  if (s.has("response_time_s")) p.sensitivity.response_times_s = number_list(s, "response_time_s", 0.0, 5.0);
  if (s.has("brake_scale")) p.sensitivity.brake_scales = number_list(s, "brake_scale", 0.25, 4.0);
}

}  // namespace

const Limits& AuditProfile::limits_for(const std::string& type) const {
  const auto it = classes.find(type);
  return it != classes.end() ? it->second : classes.at("default");
}

AuditProfile default_audit_profile() {
  AuditProfile p;
  p.classes = default_classes();
  // Recorded headings wobble by a few hundredths of a radian: 0.02 would call merges complete late.
  p.rules.merge_complete_yaw_rad = 0.05;
  return p;
}

AuditProfile audit_profile_from_json(const nlohmann::json& j, const std::string& source) {
  AuditProfile p = default_audit_profile();
  if (!j.is_object()) throw InputError(source, "/", "an audit profile must be a JSON object");
  const ObjectReader r(j, source, "");
  r.only_keys({"name", "rss", "rules", "classes", "smoothing_half_window_steps", "window_before_s", "window_after_s",
               "neighbour_range_m", "min_lane_time_s", "halted_speed_mps", "halt_near_end_m", "default_speed_limit_mps", "sensitivity"});
  p.name = r.string_or("name", p.name);
  if (r.has("rss")) p.rss = rss_params_from_json(j.at("rss"), source, "/rss");
  if (r.has("rules")) p.rules = rule_params_from_json(j.at("rules"), source, "/rules");
  if (r.has("classes")) read_classes(r, p);
  if (!p.classes.count("default")) r.fail("classes", "must keep a \"default\" class");
  p.smoothing_half_window_steps = static_cast<int>(r.integer_or("smoothing_half_window_steps", p.smoothing_half_window_steps, 1, 50));
  p.window_before_s = r.number_or("window_before_s", p.window_before_s, 1.0, 60.0);
  p.window_after_s = r.number_or("window_after_s", p.window_after_s, 1.0, 60.0);
  p.neighbour_range_m = r.number_or("neighbour_range_m", p.neighbour_range_m, 10.0, 1000.0);
  p.min_lane_time_s = r.number_or("min_lane_time_s", p.min_lane_time_s, 0.0, 5.0);
  p.halted_speed_mps = r.number_or("halted_speed_mps", p.halted_speed_mps, 0.0, 5.0);
  p.halt_near_end_m = r.number_or("halt_near_end_m", p.halt_near_end_m, 0.0, 1000.0);
  p.default_speed_limit_mps = r.number_or("default_speed_limit_mps", p.default_speed_limit_mps, 0.1, 100.0);
  if (r.has("sensitivity")) read_sensitivity(r, p);
  return p;
}

AuditProfile load_audit_profile(const std::string& path) {
  return audit_profile_from_json(parse_json_file(path, DuplicateKeys::kReject), path);
}

nlohmann::json audit_profile_to_json(const AuditProfile& p) {
  nlohmann::json classes = nlohmann::json::object();
  for (const auto& [type, limits] : p.classes) classes[type] = limits_to_json(limits);
  return {{"name", p.name},
          {"rss", rss_params_to_json(p.rss)},
          {"rules", rule_params_to_json(p.rules)},
          {"classes", classes},
          {"smoothing_half_window_steps", p.smoothing_half_window_steps},
          {"window_before_s", p.window_before_s},
          {"window_after_s", p.window_after_s},
          {"neighbour_range_m", p.neighbour_range_m},
          {"min_lane_time_s", p.min_lane_time_s},
          {"halted_speed_mps", p.halted_speed_mps},
          {"halt_near_end_m", p.halt_near_end_m},
          {"default_speed_limit_mps", p.default_speed_limit_mps},
          {"sensitivity", {{"response_time_s", p.sensitivity.response_times_s}, {"brake_scale", p.sensitivity.brake_scales}}}};
}

}  // namespace mg
