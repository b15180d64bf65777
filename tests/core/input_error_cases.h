// Shared by the loader tests (scenario_test.cpp, observed_trace_json_test.cpp): a table of
// one-defect mutations of a valid document, each of which must be rejected with a one-line
// InputError naming the source and the JSON path.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace mg::test_support {

// The InputError message `load` raises, or "" when it does not raise.
inline std::string input_error_of(const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct MutationCase {
  const char* what;
  std::function<void(nlohmann::json&)> mutate;
  const char* expected;  // substring of the one-line message
};

// Applies each mutation to a copy of `valid` and loads it with `load`.
inline void expect_input_errors(const nlohmann::json& valid, const std::vector<MutationCase>& cases,
                                const std::function<void(const nlohmann::json&)>& load) {
  for (const auto& c : cases) {
    nlohmann::json j = valid;
    c.mutate(j);
    const std::string message = input_error_of([&] { load(j); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.what << ": got '" << message << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.what << ": message must be one line";
  }
}

}  // namespace mg::test_support
