// Small CommonRoad recordings made in the tests (shared by tests/recording and tests/audit): a
// straight road along +x with an on-ramp (lanelet 1, y in [-3.5, 0], ending at x = 200) and two
// main lanes (lanelets 2 and 3, up to x = 400), and vehicles given as (x, y, speed, heading) per step.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace mg::test {

struct SyntheticVehicle {
  int id = 1;
  std::vector<std::array<double, 4>> xyv;  // x_m, y_m, speed_mps, orientation_rad per time step from 0
  std::string type = "car";
};

inline std::string num_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  return buf;
}

inline std::string bound_xml(const char* tag, double y, double x_end) {
  return std::string("<") + tag + "><point><x>0</x><y>" + num_text(y) + "</y></point><point><x>" + num_text(x_end) +
         "</x><y>" + num_text(y) + "</y></point></" + tag + ">";
}

inline std::string lanelet_xml(int id, double y_right, double x_end, const std::string& extra) {
  return "<lanelet id=\"" + std::to_string(id) + "\">" + bound_xml("leftBound", y_right + 3.5, x_end) +
         bound_xml("rightBound", y_right, x_end) + extra + "</lanelet>\n";
}

inline std::string state_xml(const char* tag, const std::array<double, 4>& s, int step) {
  return std::string("<") + tag + "><position><point><x>" + num_text(s[0]) + "</x><y>" + num_text(s[1]) +
         "</y></point></position><orientation><exact>" + num_text(s[3]) + "</exact></orientation><time><exact>" + std::to_string(step) +
         "</exact></time><velocity><exact>" + num_text(s[2]) + "</exact></velocity></" + tag + ">";
}

inline std::string vehicle_xml(const SyntheticVehicle& v, const std::string& version) {
  const bool v2018 = version == "2018b";
  std::string x = v2018 ? "<obstacle id=\"" + std::to_string(v.id) + "\"><role>dynamic</role>"
                        : "<dynamicObstacle id=\"" + std::to_string(v.id) + "\">";
  x += "<type>" + v.type + "</type><shape><rectangle><length>4.5</length><width>1.8</width></rectangle></shape>";
  x += state_xml("initialState", v.xyv.front(), 0) + "<trajectory>";
  for (std::size_t i = 1; i < v.xyv.size(); ++i) x += state_xml("state", v.xyv[i], static_cast<int>(i));
  x += "</trajectory>";
  return x + (v2018 ? "</obstacle>\n" : "</dynamicObstacle>\n");
}

inline std::string synthetic_recording_xml(const std::vector<SyntheticVehicle>& vehicles, const std::string& version = "2020a") {
  std::string x = "<?xml version=\"1.0\"?>\n<commonRoad commonRoadVersion=\"" + version +
                  "\" benchmarkID=\"TEST_Synthetic-1\" timeStepSize=\"0.1\">\n";
  x += lanelet_xml(1, -3.5, 200, "<adjacentLeft ref=\"2\" drivingDir=\"same\"/>");
  x += lanelet_xml(2, 0.0, 400, "<adjacentLeft ref=\"3\" drivingDir=\"same\"/><adjacentRight ref=\"1\" drivingDir=\"same\"/>");
  x += lanelet_xml(3, 3.5, 400, "<adjacentRight ref=\"2\" drivingDir=\"same\"/>");
  for (const SyntheticVehicle& v : vehicles) x += vehicle_xml(v, version);
  return x + "</commonRoad>\n";
}

// A vehicle at constant longitudinal speed from x0, its y moving from y_from to y_to by a smooth step
// centred at t_change_s (1 s either side); `steps` states, 0.1 s apart.
inline SyntheticVehicle lane_changer(int id, double x0, double speed, double y_from, double y_to, double t_change_s, int steps) {
  SyntheticVehicle v;
  v.id = id;
  for (int i = 0; i < steps; ++i) {
    const double t = 0.1 * i;
    const double u = std::clamp((t - t_change_s + 1.0) / 2.0, 0.0, 1.0);
    const double blend = u * u * (3 - 2 * u);
    const double lateral_mps = (y_to - y_from) * 6 * u * (1 - u) / 2.0;
    v.xyv.push_back({x0 + speed * t, y_from + (y_to - y_from) * blend, std::hypot(speed, lateral_mps), std::atan2(lateral_mps, speed)});
  }
  return v;
}

}  // namespace mg::test
