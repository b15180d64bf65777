// The table machinery on a structure of its own: which tables can be read in order, reading in
// table order with cross-parameter bounds, writing, and what the documentation sees of a row.
#include "core/param_table.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

namespace mg {
namespace {

using nlohmann::json;

struct Knobs {
  double low_m = 1.0;
  double high_m = 2.0;
  int count = 3;
  bool operator==(const Knobs&) const = default;
};

constexpr Param<Knobs> kRows[] = {
    param("low_m", &Knobs::low_m, "m", above(0.0), at_most(10.0), "the low end"),
    param("high_m", &Knobs::high_m, "m", at_least_param("low_m"), at_most(10.0), "the high end"),
    param("count", &Knobs::count, "", at_least(1.0), at_most(9.0), "how many"),
};
static_assert(well_formed<Knobs>(kRows));

constexpr ParamCheck<Knobs> kChecks[] = {
    {"count", "count ≤ 2 high_m", "count must be <= 2 high_m", [](const Knobs& k) { return k.count <= 2 * k.high_m; }},
};
constexpr ParamTable<Knobs> kTable{kRows, kChecks};

// A bound on a parameter declared after it could not be read in order.
constexpr Param<Knobs> kLaterBound[] = {
    param("high_m", &Knobs::high_m, "m", at_least_param("low_m"), at_most(10.0), "the high end"),
    param("low_m", &Knobs::low_m, "m", above(0.0), at_most(10.0), "the low end"),
};
static_assert(!well_formed<Knobs>(kLaterBound));
constexpr Param<Knobs> kOpenInteger[] = {param("count", &Knobs::count, "", above(0.0), at_most(9.0), "how many")};
static_assert(!well_formed<Knobs>(kOpenInteger));
constexpr Param<Knobs> kTwice[] = {
    param("low_m", &Knobs::low_m, "m", above(0.0), at_most(10.0), "the low end"),
    param("low_m", &Knobs::high_m, "m", above(0.0), at_most(10.0), "the high end"),
};
static_assert(!well_formed<Knobs>(kTwice));
constexpr Param<Knobs> kEmptyRange[] = {param("low_m", &Knobs::low_m, "m", above(5.0), at_most(5.0), "the low end")};
static_assert(!well_formed<Knobs>(kEmptyRange));

Knobs read(const json& j) { return read_params(kTable, ObjectReader(j, "k.json", "/knobs")); }

std::string error_of(const json& j) {
  try {
    read(j);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParamTable, AbsentKeysKeepTheDefaults) { EXPECT_EQ(read(json::object()), Knobs{}); }

TEST(ParamTable, ReadsInTableOrderWithCrossParameterBounds) {
  EXPECT_EQ(read(json{{"high_m", 5.0}, {"low_m", 4.0}}), (Knobs{4.0, 5.0, 3}));
  EXPECT_EQ(error_of(json{{"low_m", 4.0}, {"high_m", 3.0}}), "k.json: /knobs/high_m: must be in [low_m = 4, 10], got 3");
  EXPECT_EQ(error_of(json{{"low_m", 0}}), "k.json: /knobs/low_m: must be > 0, got 0");
  EXPECT_EQ(error_of(json{{"count", 0}}), "k.json: /knobs/count: must be in [1, 9], got 0");
  EXPECT_EQ(error_of(json{{"count", 5}}), "k.json: /knobs/count: count must be <= 2 high_m");
  EXPECT_EQ(error_of(json{{"colour", 5}}), "k.json: /knobs/colour: unknown key");
}

TEST(ParamTable, WritesEveryParameterIntegersAsIntegers) {
  const json j = params_to_json(kTable, Knobs{0.5, 6.0, 4});
  EXPECT_EQ(j, (json{{"low_m", 0.5}, {"high_m", 6.0}, {"count", 4}}));
  EXPECT_TRUE(j.at("count").is_number_integer());
  EXPECT_EQ(read(j), (Knobs{0.5, 6.0, 4}));
}

TEST(ParamTable, TheDocumentationSeesDefaultsAndConstraints) {
  const auto infos = param_infos(kTable);
  ASSERT_EQ(infos.size(), 3u);
  EXPECT_EQ(infos[1].name, "high_m");
  EXPECT_DOUBLE_EQ(infos[1].default_value, 2.0);
  EXPECT_EQ(infos[1].lo.param, "low_m");
  EXPECT_EQ(infos[2].type, ParamType::kInteger);
  EXPECT_EQ(infos[2].constraint, "count ≤ 2 high_m");
  EXPECT_TRUE(declares(kTable, "count"));
  EXPECT_FALSE(declares(kTable, "colour"));
}

}  // namespace
}  // namespace mg
