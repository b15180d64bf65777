// Exec planners (planner/exec_planner.h) against the purpose-written planner
// process tests/planner/exec_helpers/fake_exec_planner.cpp: a correct one answers through one
// reused child; each misbehaviour is a PlannerFault of its kind, within the timeout, with no
// process left; a command that does not answer hello cannot start. Timing bounds are generous.
#include <chrono>
#include <ostream>
#include <regex>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "core/scenario.h"
#include "planner/exec_planner.h"
#include "planner/planner_fault.h"
#include "process_probe.h"
#include "tests/support/std4_scenario.h"

namespace mg {
namespace {

std::string fake(const std::string& mode) { return std::string("exec:") + MG_FAKE_EXEC_PLANNER + " " + mode; }

long pid_in(const std::string& message) {
  std::smatch m;
  return std::regex_search(message, m, std::regex("\\(pid ([0-9]+)\\)")) ? std::stol(m[1]) : -1;
}

long answering_pid(const std::string& name) {
  const PlanOutput out = make_exec_planner(name)->plan(initial_snapshot(test::std4()));
  return out.annotation->to_json().at("pid").get<long>();
}

TEST(ExecPlanner, ACorrectPlannerAnswersWithItsCommandAndAnnotation) {
  auto planner = make_exec_planner(fake("echo"));
  EXPECT_EQ(planner->name(), fake("echo"));
  const PlanOutput out = planner->plan(initial_snapshot(test::std4()));
  ASSERT_EQ(out.path.size(), 2u);
  EXPECT_EQ(out.path[0].x_m, test::std4().ego.x_m);
  EXPECT_EQ(out.target_speed_mps, test::std4().ego.speed_mps);
  EXPECT_EQ(out.annotation->to_json().at("mode"), "echo");
  EXPECT_EQ(out.mode, "echo") << "an annotation's mode names the command's";
  ASSERT_TRUE(exec_planner_identity(fake("echo")));
  EXPECT_EQ(exec_planner_identity(fake("echo"))->name, "fake-echo");
}

TEST(ExecPlanner, OneChildPerThreadIsReusedAcrossScenarios) {
  const long first = answering_pid(fake("echo"));
  EXPECT_EQ(answering_pid(fake("echo")), first);
  long other = -1;
  std::thread([&] { other = answering_pid(fake("echo")); }).join();
  EXPECT_NE(other, first);
  EXPECT_TRUE(test::group_gone_soon(other));  // the thread's child ended with the thread
}

struct Misbehaviour {
  const char* mode;
  const char* kind;
};
void PrintTo(const Misbehaviour& m, std::ostream* os) { *os << m.mode; }

class ExecPlannerFault : public ::testing::TestWithParam<Misbehaviour> {};

TEST_P(ExecPlannerFault, IsAFindingOfItsKindAndLeavesNoProcess) {
  set_exec_options({0.5, 30.0, ""});
  auto planner = make_exec_planner(fake(GetParam().mode));
  const auto start = std::chrono::steady_clock::now();
  try {
    planner->plan(initial_snapshot(test::std4()));
    FAIL() << "no fault";
  } catch (const PlannerFault& fault) {
    EXPECT_EQ(fault.kind, GetParam().kind) << fault.what();
    EXPECT_NE(std::string(fault.what()).find("planner process '" + fake(GetParam().mode) + "'"), std::string::npos);
    const long pid = pid_in(fault.what());
    ASSERT_GT(pid, 0) << fault.what();
    EXPECT_TRUE(test::group_gone_soon(pid)) << fault.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

INSTANTIATE_TEST_SUITE_P(Modes, ExecPlannerFault,
                         ::testing::Values(Misbehaviour{"crash", kFaultExit}, Misbehaviour{"hang", kFaultTimeout},
                                           Misbehaviour{"garbage", kFaultReply}, Misbehaviour{"nan", kFaultReply},
                                           Misbehaviour{"bad-path", kFaultReply}),
                         [](const auto& info) { return std::regex_replace(info.param.mode, std::regex("-"), "_"); });

TEST(ExecPlanner, TheChildIsRestartedForTheNextScenarioAfterAFault) {
  long pids[2] = {-1, -1};
  for (long& pid : pids) {
    try {
      make_exec_planner(fake("crash"))->plan(initial_snapshot(test::std4()));
    } catch (const PlannerFault& fault) {
      EXPECT_EQ(fault.kind, kFaultExit);
      EXPECT_NE(std::string(fault.what()).find("killed by signal 6"), std::string::npos) << fault.what();
      pid = pid_in(fault.what());
    }
  }
  EXPECT_GT(pids[0], 0);
  EXPECT_GT(pids[1], 0);
  EXPECT_NE(pids[0], pids[1]);
}

TEST(ExecPlanner, ACommandThatExitsBeforeHelloCannotStart) {
  try {
    start_exec_planner(fake("no-hello"));
    FAIL() << "started";
  } catch (const ExecStartError& e) {
    EXPECT_NE(std::string(e.what()).find("exited with status 3 before answering hello"), std::string::npos) << e.what();
    EXPECT_TRUE(test::group_gone_soon(pid_in(e.what())));
  }
  EXPECT_THROW(start_exec_planner("exec:/nonexistent/planner"), ExecStartError);
}

// hello has its own timeout: a planner that loads a model for 3 s starts, whatever the per-call
// timeout; one that never answers fails after the start timeout.
TEST(ExecPlanner, HelloWaitsForTheStartTimeoutNotTheCallTimeout) {
  set_exec_options({0.5, 30.0, ""});
  EXPECT_EQ(start_exec_planner(fake("slow-hello")).name, "fake-slow-hello");
  set_exec_options({30.0, 0.3, ""});
  try {
    start_exec_planner(fake("silent-hello"));
    FAIL() << "started";
  } catch (const ExecStartError& e) {
    EXPECT_NE(std::string(e.what()).find("did not answer hello within 0.3 s"), std::string::npos) << e.what();
    EXPECT_TRUE(test::group_gone_soon(pid_in(e.what())));
  }
  set_exec_options({});
}

TEST(ExecPlanner, StartReturnsTheHelloAndEndsTheChild) {
  const PlannerIdentity id = start_exec_planner(fake("echo"));
  EXPECT_EQ(id.name, "fake-echo");
  EXPECT_EQ(id.version, "1");
}

}  // namespace
}  // namespace mg
