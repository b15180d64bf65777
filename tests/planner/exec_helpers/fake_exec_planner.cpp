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
#include <signal.h>
#include <unistd.h>

#include <charconv>
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

std::string command_for(const std::string& observe) {
  const double x = ego_number(observe, "x_m"), y = ego_number(observe, "y_m");
  std::string out = R"({"type":"command","path":[[)";
  append_number(out, x);
  out += ',';
  append_number(out, y);
  out += "],[";
  append_number(out, x + 100.0);
  out += ',';
  append_number(out, y);
  out += R"(]],"target_speed_mps":)";
  append_number(out, ego_number(observe, "speed_mps"));
  out += R"(,"accel_limit_mps2":2.0,"annotation":{"mode":"echo","pid":)" + std::to_string(getpid()) + "}}";
  return out;
}

std::string reply_to(const std::string& mode, const std::string& line) {
  const bool observe = line.find(R"("type":"observe")") != std::string::npos;
  const std::string type = observe ? "observe" : nlohmann::json::parse(line).at("type").get<std::string>();
  if (type == "hello" && mode == "silent-hello") pause();
  if (type == "hello" && mode == "slow-hello") sleep(3);
  if (type == "hello") return R"({"type":"hello","name":"fake-)" + mode + R"(","version":"1"})";
  if (type == "reset") return R"({"type":"ready"})";
  if (type == "bye") return "";
  if (mode == "crash") std::abort();
  if (mode == "hang") pause();
  if (mode == "garbage") return "this is not JSON";
  if (mode == "nan") return R"({"type":"command","path":[[0,0],[100,0]],"target_speed_mps":NaN,"accel_limit_mps2":2})";
  if (mode == "stubborn") usleep(300 * 1000);
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
