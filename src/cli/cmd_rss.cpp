// mergeguard rss longitudinal|lateral: one JSON object on stdin -> {"distance_m": ...} (spec §10).
#include <iostream>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "core/json_reader.h"
#include "core/rss.h"

namespace mg::cli {
namespace {

constexpr double kMaxSpeed = 100.0;   // m/s, same bound as scenario files
constexpr double kMaxLength = 30.0;   // m
constexpr double kMaxTime = 10.0;     // s
constexpr double kMaxAccel = 15.0;    // m/s2

double rss_longitudinal_from(const ObjectReader& r) {
  r.only_keys({"rear_speed_mps", "front_speed_mps", "rear_length_m", "front_length_m", "response_time_s",
               "accel_max_mps2", "brake_min_mps2", "brake_max_mps2"});
  LongitudinalInput in{};
  in.rear_speed_mps = r.number("rear_speed_mps", 0.0, kMaxSpeed);
  in.front_speed_mps = r.number("front_speed_mps", 0.0, kMaxSpeed);
  in.rear_length_m = r.number("rear_length_m", 0.0, kMaxLength);
  in.front_length_m = r.number("front_length_m", 0.0, kMaxLength);
  in.response_time_s = r.number("response_time_s", 0.0, kMaxTime);
  in.accel_max_mps2 = r.number("accel_max_mps2", 0.0, kMaxAccel);
  in.brake_min_mps2 = r.positive("brake_min_mps2", kMaxAccel);
  in.brake_max_mps2 = r.positive("brake_max_mps2", kMaxAccel);
  return rss_longitudinal_m(in);
}

double rss_lateral_from(const ObjectReader& r) {
  r.only_keys({"left_lat_speed_mps", "right_lat_speed_mps", "left_width_m", "right_width_m", "response_time_s",
               "lat_accel_max_mps2", "lat_brake_min_mps2", "fluctuation_margin_m"});
  LateralInput in{};
  in.left_lat_speed_mps = r.number("left_lat_speed_mps", -kMaxSpeed, kMaxSpeed);
  in.right_lat_speed_mps = r.number("right_lat_speed_mps", -kMaxSpeed, kMaxSpeed);
  in.left_width_m = r.number("left_width_m", 0.0, 10.0);
  in.right_width_m = r.number("right_width_m", 0.0, 10.0);
  in.response_time_s = r.number("response_time_s", 0.0, kMaxTime);
  in.lat_accel_max_mps2 = r.number("lat_accel_max_mps2", 0.0, kMaxAccel);
  in.lat_brake_min_mps2 = r.positive("lat_brake_min_mps2", kMaxAccel);
  in.fluctuation_margin_m = r.number("fluctuation_margin_m", 0.0, 10.0);
  return rss_lateral_m(in);
}

int run_rss(const std::vector<std::string>& args) {
  CLI::App app("RSS safe distance (RCPP eq. 1 or 2) of one JSON object read from stdin", "mergeguard rss");
  std::string kind;
  app.add_option("kind", kind, "longitudinal or lateral")->required()->check(CLI::IsMember({"longitudinal", "lateral"}));
  if (!parse_args(app, args)) return kExitOk;
  const auto json = parse_json_stream(std::cin, "<stdin>");
  const ObjectReader reader(json, "<stdin>", "");
  const double d = kind == "longitudinal" ? rss_longitudinal_from(reader) : rss_lateral_from(reader);
  std::cout << nlohmann::json{{"distance_m", d}}.dump() << "\n";
  return kExitOk;
}

}  // namespace

Command rss_command() {
  return {"rss", "rss longitudinal|lateral < INPUT.json", run_rss};
}

}  // namespace mg::cli
