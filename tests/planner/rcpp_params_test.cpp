// RCPP's own tunables (planner/rcpp_params.h): read from params.planner's pass-through object,
// the defaults for the keys it does not set, a table whose units agree with its keys.
#include "planner/rcpp_params.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/params.h"

namespace mg {
namespace {

using nlohmann::json;

TEST(RcppParams, NothingSetGivesTheDefaults) { EXPECT_EQ(rcpp_params(PlannerParams{}), RcppParams{}); }

TEST(RcppParams, ReadsTheValuesSetAndDefaultsTheRest) {
  PlannerParams p;
  p.tunables = {{"pf_road_beta", 0.7}, {"kappa_candidates", 3}};
  const RcppParams r = rcpp_params(p);
  EXPECT_DOUBLE_EQ(r.pf_road_beta, 0.7);
  EXPECT_EQ(r.kappa_candidates, 3);
  EXPECT_DOUBLE_EQ(r.cost_time_weight, RcppParams{}.cost_time_weight);
}

TEST(RcppParams, AValueOutOfRangeIsAnInputError) {
  PlannerParams p;
  p.tunables = {{"kappa_min_per_m", 0.5}, {"kappa_max_per_m", 0.1}};
  EXPECT_THROW(rcpp_params(p), InputError);
}

TEST(RcppParams, UnitsMatchTheKeysAndDefaultsLieInTheirRanges) {
  for (const ParamInfo& p : param_infos(rcpp_param_table())) {
    const std::string key(p.name);
    std::string unit;
    if (key.ends_with("_per_m")) unit = "1/m";
    else if (key.ends_with("_mps2")) unit = "m/s²";
    else if (key.ends_with("_m")) unit = "m";
    if (!unit.empty()) {
      EXPECT_EQ(p.unit, unit) << key;
    }
    if (p.lo.param.empty()) {
      EXPECT_TRUE(p.lo.open ? p.default_value > p.lo.value : p.default_value >= p.lo.value) << key;
    }
    EXPECT_TRUE(p.default_value <= p.hi.value) << key;
  }
}

// Core's own planner keys and RCPP's are disjoint: a key is read by one table only.
TEST(RcppParams, NoKeyIsAlsoCores) {
  for (const ParamInfo& p : param_infos(rcpp_param_table()))
    EXPECT_FALSE(declares(planner_param_table(), p.name)) << p.name;
}

}  // namespace
}  // namespace mg
