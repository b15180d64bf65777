#include "planner/planner.h"

#include <algorithm>

namespace mg {

std::vector<std::pair<std::string, std::string>> PlanAnnotation::describe() const {
  std::vector<std::pair<std::string, std::string>> lines;
  const nlohmann::json j = to_json();
  if (!j.is_object()) return {{"annotation", j.dump()}};
  for (const auto& [key, value] : j.items()) lines.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  return lines;
}

nlohmann::json plan_record_to_json(const PlanRecord& r) {
  nlohmann::json j{{"time_s", r.time_s}, {"mode", r.mode}, {"reason", r.reason}};
  if (r.annotation) j["annotation"] = r.annotation->to_json();
  return j;
}

WorldSnapshot initial_snapshot(const Scenario& s) {
  WorldSnapshot w;
  w.time_s = 0.0;
  w.ego.x_m = s.ego.x_m;
  w.ego.y_m = s.ego.y_m;
  w.ego.vx_mps = s.ego.speed_mps;
  for (const MainVehicle& v : s.vehicles) {
    ObservedVehicle o;
    o.id = v.id;
    o.state.x_m = v.x_m;
    o.state.y_m = v.lane * s.road.lane_width_m;
    o.state.vx_mps = v.speed_mps;
    o.size = v.size;
    o.limits = v.limits;
    o.v2v_capable = v.v2v.capable;
    w.others.push_back(o);
  }
  std::sort(w.others.begin(), w.others.end(), [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.id < b.id; });
  w.setup = &s;
  return w;
}

}  // namespace mg
