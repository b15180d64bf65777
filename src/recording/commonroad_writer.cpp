#include "recording/commonroad_writer.h"

#include <cstdio>

namespace mg {
namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string bound(const char* tag, const std::vector<Point2>& pts) {
  std::string x = std::string("<") + tag + ">";
  for (const Point2& p : pts) x += "<point><x>" + num(p.x_m) + "</x><y>" + num(p.y_m) + "</y></point>";
  return x + "</" + tag + ">\n";
}

std::string lanelet(const Lanelet& l) {
  std::string x = "<lanelet id=\"" + std::to_string(l.id) + "\">\n" + bound("leftBound", l.left_bound) + bound("rightBound", l.right_bound);
  for (const int p : l.predecessors) x += "<predecessor ref=\"" + std::to_string(p) + "\"/>";
  for (const int s : l.successors) x += "<successor ref=\"" + std::to_string(s) + "\"/>";
  if (l.adjacent_left) x += "<adjacentLeft ref=\"" + std::to_string(*l.adjacent_left) + "\" drivingDir=\"same\"/>";
  if (l.adjacent_right) x += "<adjacentRight ref=\"" + std::to_string(*l.adjacent_right) + "\" drivingDir=\"same\"/>";
  for (const std::string& t : l.types) x += "<laneletType>" + escaped(t) + "</laneletType>";
  if (l.speed_limit_mps) x += "<speedLimit>" + num(*l.speed_limit_mps) + "</speedLimit>";
  return x + "\n</lanelet>\n";
}

std::string state(const char* tag, const RecordedState& s) {
  std::string x = std::string("<") + tag + "><position><point><x>" + num(s.x_m) + "</x><y>" + num(s.y_m) + "</y></point></position>";
  if (s.orientation_rad) x += "<orientation><exact>" + num(*s.orientation_rad) + "</exact></orientation>";
  x += "<time><exact>" + std::to_string(s.time_step) + "</exact></time>";
  if (s.speed_mps) x += "<velocity><exact>" + num(*s.speed_mps) + "</exact></velocity>";
  if (s.accel_mps2) x += "<acceleration><exact>" + num(*s.accel_mps2) + "</exact></acceleration>";
  return x + "</" + tag + ">\n";
}

std::string vehicle(const RecordedVehicle& v) {
  std::string x = "<dynamicObstacle id=\"" + std::to_string(v.id) + "\"><type>" + escaped(v.type) + "</type><shape><rectangle><length>" +
                  num(v.length_m) + "</length><width>" + num(v.width_m) + "</width></rectangle></shape>\n";
  x += state("initialState", v.states.front());
  x += "<trajectory>\n";
  for (std::size_t i = 1; i < v.states.size(); ++i) x += state("state", v.states[i]);
  return x + "</trajectory></dynamicObstacle>\n";
}

}  // namespace

std::string recording_to_xml(const Recording& r) {
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<commonRoad commonRoadVersion=\"2020a\" benchmarkID=\"" +
                  escaped(r.benchmark_id) + "\" timeStepSize=\"" + num(r.time_step_s) + "\" author=\"mergeguard\">\n";
  for (const Lanelet& l : r.lanelets) x += lanelet(l);
  for (const RecordedVehicle& v : r.vehicles) x += vehicle(v);
  return x + "</commonRoad>\n";
}

}  // namespace mg
