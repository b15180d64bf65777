// The parameter tables of docs/baselines.md as the baselines' tests read them: the default the
// document gives a parameter, so that a test can hold it to the planner's own table.
#pragma once

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace mg::test {

// The number in the default column of the row "| `name` | default | ..." of docs/baselines.md.
inline std::optional<double> documented_default(const std::string& name) {
  std::ifstream in(std::string(MG_SOURCE_DIR) + "/docs/baselines.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string row = "| `" + name + "` | ";
  const std::size_t at = text.str().find(row);
  if (at == std::string::npos) return std::nullopt;
  return std::strtod(text.str().c_str() + at + row.size(), nullptr);
}

}  // namespace mg::test
