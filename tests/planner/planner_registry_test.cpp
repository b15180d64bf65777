// The open planner registry (planner/planner_registry.h): the built-ins keep their
// names and order, a registered planner is made and listed like them, and bad registrations are
// refused. The registry is process-wide, so the planner registered here is a sane one (RCPP
// under another name): the harness tests that iterate planner_names() may then meet it too.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "planner/planner_registry.h"
#include "planner/rcpp_planner.h"

namespace mg {
namespace {

constexpr const char* kRegisteredName = "test-registered-rcpp";

class RenamedRcpp : public Planner {
 public:
  std::string name() const override { return kRegisteredName; }
  PlanOutput plan(const WorldSnapshot& w) override { return rcpp_.plan(w); }

 private:
  RcppPlanner rcpp_{false};
};

void register_once() {
  static const bool registered = [] {
    register_planner(kRegisteredName, [] { return std::make_unique<RenamedRcpp>(); });
    return true;
  }();
  (void)registered;
}

TEST(PlannerRegistry, BuiltInsComeFirstInTheirOrder) {
  const std::vector<std::string> names = planner_names();
  ASSERT_GE(names.size(), 5u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 5),
            (std::vector<std::string>{"rcpp", "rcpp-coop", "tripfield", "mobil", "frenet"}));
}

TEST(PlannerRegistry, ARegisteredPlannerIsMadeAndListedLast) {
  register_once();
  const std::vector<std::string> names = planner_names();
  EXPECT_EQ(names.back(), kRegisteredName);
  const auto p = make_planner(kRegisteredName);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->name(), kRegisteredName);
  EXPECT_NE(make_planner(kRegisteredName).get(), p.get());  // a fresh planner per call
}

TEST(PlannerRegistry, RefusesEmptyAndDuplicateNamesAndEmptyFactories) {
  register_once();
  const PlannerFactory factory = [] { return std::make_unique<RenamedRcpp>(); };
  EXPECT_THROW(register_planner("", factory), std::invalid_argument);
  EXPECT_THROW(register_planner("rcpp", factory), std::invalid_argument);
  EXPECT_THROW(register_planner(kRegisteredName, factory), std::invalid_argument);
  EXPECT_THROW(register_planner("test-no-factory", PlannerFactory{}), std::invalid_argument);
  const std::vector<std::string> names = planner_names();
  EXPECT_EQ(std::count(names.begin(), names.end(), "rcpp"), 1);
  EXPECT_EQ(std::count(names.begin(), names.end(), "test-no-factory"), 0);
}

TEST(PlannerRegistry, ExecNamesAreMadeNotRegistered) {
  EXPECT_THROW(register_planner("exec:true", [] { return std::make_unique<RenamedRcpp>(); }), std::invalid_argument);
  const auto p = make_planner("exec:true");  // no process starts before the first plan()
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->name(), "exec:true");
  EXPECT_EQ(make_planner("exec:"), nullptr);
}

}  // namespace
}  // namespace mg
