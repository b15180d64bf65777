// The messages of the exec planner protocol "mergeguard-planner/1" (docs/planner_protocol.md,
// docs/planner_protocol.schema.json): the requests mergeguard writes and the checks of the
// replies it reads. Transport and processes are elsewhere (planner/child_process.h,
// planner/exec_planner.h): this file is the contract alone.
#pragma once

#include <stdexcept>
#include <string>

#include "core/scenario.h"
#include "planner/planner.h"

namespace mg {

inline constexpr const char* kPlannerProtocol = "mergeguard-planner/1";

// A reply the protocol does not allow; what() says what is wrong in one line.
struct ProtocolError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a planner process says it is in its hello reply.
struct PlannerIdentity {
  std::string name;
  std::string version;
};

std::string hello_request();
// What a planner may know before it starts: the road, its own vehicle, the parameters, in the
// scenario format's keys; nothing of the other vehicles.
std::string reset_request(const PlannerSetup& setup);
std::string observe_request(const WorldSnapshot& world);
std::string bye_request();

// The replies, checked against the schema (ProtocolError otherwise). A command's path must have
// at least two points, finite coordinates and strictly increasing x; its speeds must be finite
// and >= 0; outbox messages must name a vehicle of `world.others`. The annotation (any JSON object)
// lands in PlanOutput::decision.annotation.
PlannerIdentity parse_hello_reply(const std::string& line);
void parse_ready_reply(const std::string& line);
PlanOutput parse_command_reply(const std::string& line, const WorldSnapshot& world);

}  // namespace mg
