// Small CommonRoad recordings made in the tests (shared by tests/recording and tests/audit): a
// straight road along +x with an on-ramp (lanelet 1, y in [-3.5, 0], ending at x = 200) and two
// main lanes (lanelets 2 and 3, up to x = 400), and vehicles given as (x, y, speed, heading) per step.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace mg::test {

struct SyntheticVehicle {
  int id = 1;
  std::vector<std::array<double, 4>> xyv;  // x_m, y_m, speed_mps, orientation_rad per time step from first_step
  std::string type = "car";
  int first_step = 0;  // recorded from this time step on
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
  x += state_xml("initialState", v.xyv.front(), v.first_step) + "<trajectory>";
  for (std::size_t i = 1; i < v.xyv.size(); ++i) x += state_xml("state", v.xyv[i], v.first_step + static_cast<int>(i));
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

// The states of `v` from step `from` on (recorded only from then).
inline SyntheticVehicle recorded_from(SyntheticVehicle v, int from) {
  v.xyv.erase(v.xyv.begin(), v.xyv.begin() + from);
  v.first_step = from;
  return v;
}

// An urban junction (2020a, every lanelet typed urban, scenarioTags urban and intersection): an
// eastbound lane (lanelets 10 and 11, y in [0, 3.5], x to 200) and a lane from the south
// (lanelet 20, centre x = 90 from y = -40) turning right into lanelet 11 with a 10 m radius.
inline std::string urban_junction_xml(const std::vector<SyntheticVehicle>& vehicles) {
  const auto pt = [](double x, double y) { return "<point><x>" + num_text(x) + "</x><y>" + num_text(y) + "</y></point>"; };
  const auto turn = [&](double radius, double x_straight) {
    std::string b = pt(x_straight, -40) + pt(x_straight, -8.25);
    for (int k = 1; k <= 8; ++k) {
      const double a = M_PI - k * (M_PI / 2) / 8;  // from west of the centre (100, -8.25) to north of it
      b += pt(100 + radius * std::cos(a), -8.25 + radius * std::sin(a));
    }
    return b;
  };
  const std::string urban = "<laneletType>urban</laneletType>";
  std::string x = "<?xml version=\"1.0\"?>\n<commonRoad commonRoadVersion=\"2020a\" benchmarkID=\"TEST_Junction-1\" timeStepSize=\"0.1\">\n"
                  "<scenarioTags><urban/><intersection/></scenarioTags>\n";
  x += "<lanelet id=\"10\">" + bound_xml("leftBound", 3.5, 100) + bound_xml("rightBound", 0, 100) + "<successor ref=\"11\"/>" + urban + "</lanelet>\n";
  x += "<lanelet id=\"11\"><leftBound>" + pt(100, 3.5) + pt(200, 3.5) + "</leftBound><rightBound>" + pt(100, 0) + pt(200, 0) +
       "</rightBound><predecessor ref=\"10\"/><predecessor ref=\"20\"/>" + urban + "<speedLimit>13.89</speedLimit></lanelet>\n";
  x += "<lanelet id=\"20\"><leftBound>" + turn(11.75, 88.25) + "</leftBound><rightBound>" + turn(8.25, 91.75) + "</rightBound><successor ref=\"11\"/>" +
       urban + "</lanelet>\n";
  for (const SyntheticVehicle& v : vehicles) x += vehicle_xml(v, "2020a");
  return x + "</commonRoad>\n";
}

// A vehicle turning right from lanelet 20 into lanelet 11 at `speed`, on the lane's centre line
// (a quarter circle of radius 10 m about (100, -8.25)), from y = -25; `steps` states.
inline SyntheticVehicle junction_turner(int id, double speed, int steps) {
  SyntheticVehicle v;
  v.id = id;
  const double straight = -8.25 + 25.0, arc = 10.0 * M_PI / 2;
  for (int i = 0; i < steps; ++i) {
    const double d = speed * 0.1 * i;
    if (d < straight) {
      v.xyv.push_back({90, -25 + d, speed, M_PI / 2});
    } else if (d < straight + arc) {
      const double a = M_PI - (d - straight) / 10.0;
      v.xyv.push_back({100 + 10 * std::cos(a), -8.25 + 10 * std::sin(a), speed, a - M_PI / 2});
    } else {
      v.xyv.push_back({100 + d - straight - arc, 1.75, speed, 0.0});
    }
  }
  return v;
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
