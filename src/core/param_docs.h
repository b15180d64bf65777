// The documentation of parameter tables (core/param_table.h), generated so that it cannot drift
// from the code: the params table of docs/scenario_format.md and the params fragments of
// docs/scenario.schema.json and docs/trace.schema.json. `mergeguard params` prints and updates
// them; a test compares the committed files with what these functions make of the tables.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/param_table.h"

namespace mg {

// A number as the documentation writes it: 5, 0.05, 1e6.
std::string doc_number(double x);
// The valid range as the documentation writes it: "[0, 5]", "(0, 10]", "[`step_s`, 5]",
// "[0, `merge_start_offset_m`)", "[1, 200], integer", with the parameter's constraint appended.
std::string doc_range(const ParamInfo& p);

// The markdown table of every parameter of `sections`, keys written "section.key": columns key,
// unit, default, valid range, meaning. Ends with a newline.
std::string params_markdown_table(const std::vector<ParamSection>& sections);

// The JSON Schema of a params object made of `sections`: an object per section, every key
// optional, no other keys; per parameter its type, range (a parameter bound as the widest range
// that parameter allows, the bound itself in the description), default and description.
nlohmann::ordered_json params_schema(const std::vector<ParamSection>& sections);

// Where docs/scenario_format.md holds the generated table: the lines between these two.
inline constexpr const char* kParamsTableBegin =
    "<!-- params table: generated from the parameter tables by `mergeguard params --update docs`; do not edit -->";
inline constexpr const char* kParamsTableEnd = "<!-- end of the generated params table -->";
// The text between the markers (std::invalid_argument when they are missing), and `text` with
// it replaced.
std::string marked_block(const std::string& text);
std::string replace_marked_block(const std::string& text, const std::string& block);

// How a committed document disagrees with the generated one, one line per difference naming the
// parameter and the field ("params.rss.response_time_s: default: 0.6 in the file, 0.5 in the
// table"); empty when they agree.
std::vector<std::string> markdown_table_differences(const std::string& committed, const std::string& generated);
std::vector<std::string> schema_differences(const nlohmann::ordered_json& committed,
                                            const nlohmann::ordered_json& generated);

}  // namespace mg
