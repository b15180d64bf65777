// libFuzzer target for the JSON input boundary (docs/fuzzing.md "Coverage-guided fuzzing"): every
// input goes through every strict loader the command line has for JSON text, the way the commands
// read it: a scenario, a corpus case, a saved observable trace, a params file (check-trace
// --params), an audit profile (the last three reject repeated keys, so they get their own parse),
// and a reply of an exec planner. A rejected input (InputError; ProtocolError for a planner's
// reply) is fine; anything else escaping, a crash or a sanitizer report is a bug. Every loader
// sees every input rather than one chosen by the input's keys, so that no mutation can route an
// input away from the loader it is exercising.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "audit/audit_profile.h"
#include "core/input_error.h"
#include "core/json_reader.h"
#include "core/observed_trace_json.h"
#include "core/params.h"
#include "core/scenario.h"
#include "fuzz/corpus_case.h"
#include "planner/exec_protocol.h"
#include "planner/planner.h"
#include "planner/planner_params.h"

namespace {

const std::string kSource = "fuzz input";

template <typename Load>
void rejected_is_fine(Load&& load) {
  try {
    load();
  } catch (const mg::InputError&) {
  }
}

// What the exec planner's replies are checked against: a world with two other vehicles (ids 1
// and 2), so that an outbox message can name a vehicle the planner observes.
const mg::WorldSnapshot& observed_world() {
  static const mg::PlannerSetup setup{};
  static const mg::WorldSnapshot world = [] {
    mg::WorldSnapshot w;
    w.others.resize(2);
    w.others[0].id = 1;
    w.others[1].id = 2;
    w.setup = &setup;
    return w;
  }();
  return world;
}

// A reply is checked against the type the protocol expects at that point of the conversation;
// the one its "type" names is the one that gets past the first check.
void planner_reply(const std::string& line, const nlohmann::json* parsed) {
  std::string type;
  if (parsed != nullptr && parsed->is_object()) {
    const auto it = parsed->find("type");
    if (it != parsed->end() && it->is_string()) type = it->get<std::string>();
  }
  try {
    if (type == "hello") mg::parse_hello_reply(line);
    else if (type == "ready") mg::parse_ready_reply(line);
    else mg::parse_command_reply(line, observed_world());
  } catch (const mg::ProtocolError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json keep_last;
  bool parsed = false;
  rejected_is_fine([&] {
    keep_last = mg::parse_json_text(text, kSource);
    parsed = true;
  });
  // The protocol reader parses a reply itself, with its own bounds: it sees unparsable text too.
  planner_reply(text, parsed ? &keep_last : nullptr);
  if (!parsed) return 0;  // the stricter parse below would reject it as well
  // As the commands read a scenario: the core fields, then the planner tunables against their tables.
  rejected_is_fine([&] { mg::planner_scenario_from_json(keep_last, kSource); });
  rejected_is_fine([&] { mg::fuzz::case_from_json(keep_last, kSource); });
  rejected_is_fine([&] {
    const nlohmann::json strict = mg::parse_json_text(text, kSource, mg::DuplicateKeys::kReject);
    rejected_is_fine([&] { mg::observed_trace_from_json(strict, kSource); });
    rejected_is_fine([&] { mg::params_from_json(strict, kSource, ""); });
    rejected_is_fine([&] { mg::audit_profile_from_json(strict, kSource); });
  });
  return 0;
}
