// A planner process for the exec protocol tests and benchmark (docs/planner_protocol.md), one
// behaviour per mode (argv[1]; further arguments are ignored: tests mark their children with one):
//   echo       correct: keeps its lane at its speed (the trivial planner the benchmark times);
//              its annotation names its pid, so that tests see which child answered
//   crash      answers hello and reset, then aborts on the first observe
//   hang       answers hello and reset, then never answers observe
//   garbage    answers observe with a line that is not JSON
//   nan        answers observe with NaN in the command (as Python's json.dumps writes it)
//   no-hello   exits with status 3 before answering hello
//   bad-path   answers observe with a path whose x decreases
//   stubborn   as echo, but takes 0.3 s per observe and ignores the end of its input (it stays
//              until killed)
//   slow-hello as echo, but takes 3 s to answer hello (a planner loading a model at start-up)
//   silent-hello  never answers hello (it stays until killed)
//   creep      never merges: keeps its lane and slows to 0.06 m/s (liveness adversary)
//   stop-short never merges: keeps its lane and stops with its front 39 m before the side lane's
//              end, then waits there (liveness adversary)
//   weave      weaves between 0.2 and 0.7 m off the side lane's centre toward the main lane, 60 m
//              a period, never back at the centre; stops as stop-short (smoothness adversary)
//   drift      drifts into the main lane 0.018 m per metre (0.09 m/s lateral at 5 m/s) at its
//              speed (slow-merge adversary)
//   pretend    out to 0.6 m off the side lane's centre and back every 40 m, never over the lane
//              line; stops as stop-short (a merge that never happens)
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

// The number after `"key":` inside the ego object. A trivial planner reads three numbers and does
// not build the whole message as a DOM (which would cost it three quarters of its time): the
// benchmark times the protocol, not a JSON library.
double ego_number(const std::string& line, const char* key) {
  const std::size_t ego = line.find("\"ego\":{");
  const std::size_t at = line.find(std::string("\"") + key + "\":", ego);
  return std::strtod(line.c_str() + at + std::strlen(key) + 3, nullptr);
}

// Numbers in the shortest text that reads back to the same double, as a planner that cares for
// its own speed writes them (snprintf's "%.17g" costs several times more to write and to read).
void append_number(std::string& out, double v) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// A command along a straight path at the ego's Y from x_from_m to x_to_m; `tail` closes the
// object after the target speed (the acceleration limit and any annotation).
std::string straight_command(double x_from_m, double x_to_m, double y_m, double speed_mps, const std::string& tail) {
  std::string out = R"({"type":"command","path":[[)";
  append_number(out, x_from_m);
  out += ',';
  append_number(out, y_m);
  out += "],[";
  append_number(out, x_to_m);
  out += ',';
  append_number(out, y_m);
  out += R"(]],"target_speed_mps":)";
  append_number(out, speed_mps);
  return out + tail;
}

std::string command_for(const std::string& observe) {
  const double x = ego_number(observe, "x_m"), y = ego_number(observe, "y_m");
  return straight_command(x, x + 100.0, y, ego_number(observe, "speed_mps"),
                          R"(,"accel_limit_mps2":2.0,"annotation":{"mode":"echo","pid":)" + std::to_string(getpid()) + "}}");
}

// What `reset` told the planner (the liveness adversaries need the side lane's end).
double g_side_lane_end_x_m = 300.0;
double g_ego_length_m = 4.8;
double g_lane_width_m = 3.5;

// Keeps the ego's lane at `speed_mps`, changing speed at most 3 m/s^2.
std::string lane_keeping_at(const std::string& observe, double speed_mps) {
  const double x = ego_number(observe, "x_m"), y = ego_number(observe, "y_m");
  return straight_command(x - 10.0, x + 100.0, y, speed_mps, R"(,"accel_limit_mps2":3.0})");
}

// Follows y(x) from 10 m behind to 200 m ahead of the ego at `speed_mps`.
template <class YOf>
std::string path_command(const std::string& observe, YOf y_of, double speed_mps) {
  const double x0 = ego_number(observe, "x_m");
  std::string out = R"({"type":"command","path":[)";
  for (int i = -10; i <= 200; ++i) {
    out += i == -10 ? "[" : ",[";
    append_number(out, x0 + i);
    out += ',';
    append_number(out, y_of(x0 + i));
    out += ']';
  }
  out += R"(],"target_speed_mps":)";
  append_number(out, speed_mps);
  out += R"(,"accel_limit_mps2":3.0})";
  return out;
}

// Braking at 1.5 m/s^2 to a stop with the front 39 m before the side lane's end.
double stop_short_speed_mps(const std::string& observe) {
  const double to_stop_m = g_side_lane_end_x_m - 39.0 - (ego_number(observe, "x_m") + 0.5 * g_ego_length_m);
  return std::min(ego_number(observe, "speed_mps"), std::sqrt(2.0 * 1.5 * std::max(0.0, to_stop_m)));
}

std::string reply_to(const std::string& mode, const std::string& line) {
  const bool observe = line.find(R"("type":"observe")") != std::string::npos;
  const std::string type = observe ? "observe" : nlohmann::json::parse(line).at("type").get<std::string>();
  if (type == "hello" && mode == "silent-hello") pause();
  if (type == "hello" && mode == "slow-hello") sleep(3);
  if (type == "hello") return R"({"type":"hello","name":"fake-)" + mode + R"(","version":"1"})";
  if (type == "reset") {
    const nlohmann::json reset = nlohmann::json::parse(line);
    g_side_lane_end_x_m = reset.at("road").value("side_lane_end_x_m", 300.0);
    g_ego_length_m = reset.at("ego").value("length_m", 4.8);
    g_lane_width_m = reset.at("road").value("lane_width_m", 3.5);
    return R"({"type":"ready"})";
  }
  if (type == "bye") return "";
  if (mode == "crash") std::abort();
  if (mode == "hang") pause();
  if (mode == "garbage") return "this is not JSON";
  if (mode == "nan") return R"({"type":"command","path":[[0,0],[100,0]],"target_speed_mps":NaN,"accel_limit_mps2":2})";
  if (mode == "stubborn") usleep(300 * 1000);
  const double side_y = -g_lane_width_m;
  if (mode == "weave")
    return path_command(line, [=](double x) { return side_y + 0.45 + 0.25 * std::sin(2.0 * M_PI * x / 60.0); },
                        stop_short_speed_mps(line));
  if (mode == "drift")
    return path_command(line, [=](double x) { return std::min(0.0, side_y + 0.018 * std::max(0.0, x)); },
                        ego_number(line, "speed_mps"));
  if (mode == "pretend")
    return path_command(line, [=](double x) { return side_y + 0.3 * (1.0 - std::cos(2.0 * M_PI * x / 40.0)); },
                        stop_short_speed_mps(line));
  if (mode == "creep") return lane_keeping_at(line, 0.06);
  if (mode == "stop-short") return lane_keeping_at(line, stop_short_speed_mps(line));
  if (mode == "bad-path") return R"({"type":"command","path":[[100,0],[0,0]],"target_speed_mps":10,"accel_limit_mps2":2})";
  return command_for(line);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "echo";
  if (mode == "no-hello") return 3;
  if (mode == "stubborn") signal(SIGPIPE, SIG_IGN);  // not even a write to a closed socket ends it
  std::ios::sync_with_stdio(false);
  std::string line;
  while (std::getline(std::cin, line)) {
    const std::string reply = reply_to(mode, line);
    if (reply.empty()) return 0;  // bye
    std::cout << reply << '\n' << std::flush;
  }
  while (mode == "stubborn") pause();
  return 0;
}
