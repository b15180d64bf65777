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
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

std::string command_for(const nlohmann::json& observe) {
  const nlohmann::json& ego = observe.at("ego");
  const double x = ego.at("x_m").get<double>(), y = ego.at("y_m").get<double>();
  return nlohmann::json{{"type", "command"},
                        {"path", {{x, y}, {x + 100.0, y}}},
                        {"target_speed_mps", ego.at("speed_mps").get<double>()},
                        {"accel_limit_mps2", 2.0},
                        {"annotation", {{"mode", "echo"}, {"pid", static_cast<long>(getpid())}}}}
      .dump();
}

std::string reply_to(const std::string& mode, const nlohmann::json& msg) {
  const std::string type = msg.at("type").get<std::string>();
  if (type == "hello") return R"({"type":"hello","name":"fake-)" + mode + R"(","version":"1"})";
  if (type == "reset") return R"({"type":"ready"})";
  if (mode == "crash") std::abort();
  if (mode == "hang") pause();
  if (mode == "garbage") return "this is not JSON";
  if (mode == "nan") return R"({"type":"command","path":[[0,0],[100,0]],"target_speed_mps":NaN,"accel_limit_mps2":2})";
  if (mode == "bad-path") return R"({"type":"command","path":[[100,0],[0,0]],"target_speed_mps":10,"accel_limit_mps2":2})";
  return command_for(msg);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "echo";
  if (mode == "no-hello") return 3;
  std::ios::sync_with_stdio(false);
  std::string line;
  while (std::getline(std::cin, line)) {
    const nlohmann::json msg = nlohmann::json::parse(line);
    if (msg.at("type") == "bye") return 0;
    std::cout << reply_to(mode, msg) << '\n' << std::flush;
  }
  return 0;
}
