// mergeguard params --markdown | --schema | --check DOCS_DIR | --update DOCS_DIR: the parameter
// documentation, generated from the parameter tables (core/param_table.h) so that it cannot drift
// from the code: the params table of DOCS_DIR/scenario_format.md and the params fragments of
// DOCS_DIR/scenario.schema.json and DOCS_DIR/trace.schema.json. --check prints one line per
// difference between those files and the tables and exits 1 if there is one (a test runs it on
// docs/); --update rewrites them. A maintainer's tool, not listed in the usage.
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/param_docs.h"
#include "core/params.h"
#include "planner/planner_params.h"

namespace mg::cli {
namespace {

using nlohmann::ordered_json;

struct DocFiles {
  std::string markdown;
  std::string scenario_schema;
  std::string trace_schema;
  explicit DocFiles(const std::string& dir)
      : markdown(dir + "/scenario_format.md"),
        scenario_schema(dir + "/scenario.schema.json"),
        trace_schema(dir + "/trace.schema.json") {}
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Key order kept: the files are written back with their other parts as they were.
ordered_json read_schema(const std::string& path) {
  try {
    return ordered_json::parse(read_text(path));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, "", std::string("malformed JSON (") + e.what() + ")");
  }
}

const ordered_json& params_of(const ordered_json& schema, const std::string& path) {
  if (!schema.contains("properties") || !schema.at("properties").contains("params"))
    throw InputError(path, "/properties/params", "missing");
  return schema.at("properties").at("params");
}

void add_prefixed(const std::string& file, const std::vector<std::string>& lines, std::vector<std::string>& out) {
  for (const std::string& l : lines) out.push_back(file + ": " + l);
}

std::vector<std::string> differences(const DocFiles& f) {
  std::vector<std::string> out;
  add_prefixed(f.markdown,
               markdown_table_differences(marked_block(read_text(f.markdown)),
                                          params_markdown_table(scenario_param_sections())),
               out);
  add_prefixed(f.scenario_schema,
               schema_differences(params_of(read_schema(f.scenario_schema), f.scenario_schema),
                                  params_schema(scenario_param_sections())),
               out);
  add_prefixed(f.trace_schema,
               schema_differences(params_of(read_schema(f.trace_schema), f.trace_schema),
                                  params_schema(trace_param_sections())),
               out);
  return out;
}

void update_schema(const std::string& path, const std::vector<ParamSection>& sections) {
  ordered_json schema = read_schema(path);
  params_of(schema, path);  // present
  schema["properties"]["params"] = params_schema(sections);
  write_file_atomic(path, schema.dump(2) + "\n");
}

void update(const DocFiles& f) {
  const std::string md = read_text(f.markdown);
  write_file_atomic(f.markdown, replace_marked_block(md, params_markdown_table(scenario_param_sections())));
  update_schema(f.scenario_schema, scenario_param_sections());
  update_schema(f.trace_schema, trace_param_sections());
}

int run_params(const std::vector<std::string>& args) {
  CLI::App app("Print, check or update the parameter documentation generated from the parameter tables",
               "mergeguard params");
  bool markdown = false;
  bool schema = false;
  std::string check_dir;
  std::string update_dir;
  auto* group = app.add_option_group("what")->require_option(1);
  group->add_flag("--markdown", markdown, "print the params table of docs/scenario_format.md");
  group->add_flag("--schema", schema, "print the params fragment of docs/scenario.schema.json");
  group->add_option("--check", check_dir, "compare the docs in this directory with the tables");
  group->add_option("--update", update_dir, "rewrite the docs in this directory from the tables");
  if (!parse_args(app, args)) return kExitOk;
  if (markdown) std::cout << params_markdown_table(scenario_param_sections());
  if (schema) std::cout << params_schema(scenario_param_sections()).dump(2) << "\n";
  if (!update_dir.empty()) update(DocFiles(update_dir));
  if (check_dir.empty()) return kExitOk;
  const std::vector<std::string> diff = differences(DocFiles(check_dir));
  for (const std::string& line : diff) std::cout << line << "\n";
  if (!diff.empty())
    std::cout << diff.size() << " difference(s); `mergeguard params --update " << check_dir << "` regenerates the docs\n";
  return diff.empty() ? kExitOk : kExitViolation;
}

}  // namespace

Command params_command() {
  return {"params", "params --markdown | --schema | --check DOCS_DIR | --update DOCS_DIR", run_params, true};
}

}  // namespace mg::cli
