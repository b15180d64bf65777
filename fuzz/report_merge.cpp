#include "fuzz/report_merge.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "core/input_error.h"
#include "core/json_reader.h"

namespace mg::fuzz {
namespace {

using nlohmann::json;

// One shard's summary as read back: what the campaign was and what it found.
struct Shard {
  std::string path;
  CampaignOptions options;
  CampaignResult result;
};

const json& field(const json& j, const std::string& key, const std::string& source, const std::string& path) {
  if (!j.is_object() || !j.contains(key)) throw InputError(source, path + "/" + key, "missing (not a mergeguard campaign report.json?)");
  return j.at(key);
}

// A field of the expected JSON type: a report.json edited by hand, or another program's file, is
// refused naming the file and the key rather than with the JSON library's message.
std::string text_field(const json& j, const std::string& key, const std::string& source, const std::string& path) {
  const json& v = field(j, key, source, path);
  if (!v.is_string()) throw InputError(source, path + "/" + key, "expected a string");
  return v.get<std::string>();
}

bool flag_field(const json& j, const std::string& key, const std::string& source, const std::string& path) {
  const json& v = field(j, key, source, path);
  if (!v.is_boolean()) throw InputError(source, path + "/" + key, "expected true or false");
  return v.get<bool>();
}

std::uint64_t count(const json& j, const std::string& key, const std::string& source, const std::string& path) {
  const json& v = field(j, key, source, path);
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0))
    throw InputError(source, path + "/" + key, "expected a count");
  return v.get<std::uint64_t>();
}

std::map<std::string, std::uint64_t> counts(const json& j, const std::string& key, const std::string& source) {
  std::map<std::string, std::uint64_t> out;
  const json& m = field(j, key, source, "");
  if (!m.is_object()) throw InputError(source, "/" + key, "expected an object");
  for (const auto& [k, v] : m.items()) out[k] = count(m, k, source, "/" + key);
  return out;
}

MarginStats margin_of(const json& m, const std::string& source, const std::string& path) {
  MarginStats s;
  s.unit = text_field(m, "unit", source, path);
  s.scenarios = count(m, "scenarios", source, path);
  s.exercised = count(m, "exercised", source, path);
  s.violated = count(m, "violated", source, path);
  const json& sum = field(m, "sum_micro", source, path);
  if (!sum.is_number_integer()) throw InputError(source, path + "/sum_micro", "expected an integer");
  s.sum_micro = sum.get<std::int64_t>();
  const json& min = field(m, "min", source, path);
  if (s.exercised > 0 && !min.is_number()) throw InputError(source, path + "/min", "expected a number");
  if (s.exercised > 0) s.min = min.get<double>();
  const json& bins = field(m, "bins", source, path);
  if (!bins.is_array() || bins.size() != s.bins.size()) throw InputError(source, path + "/bins", "expected " + std::to_string(s.bins.size()) + " bins");
  for (std::size_t b = 0; b < s.bins.size(); ++b) s.bins[b] = count(bins[b], "count", source, path + "/bins/" + std::to_string(b));
  return s;
}

SignatureRecord signature_of_entry(const json& e, const std::string& source, const std::string& path) {
  SignatureRecord r;
  r.signature = {text_field(e, "planner", source, path), text_field(e, "property", source, path),
                 text_field(e, "rule", source, path), text_field(e, "party", source, path)};
  r.count = count(e, "scenarios", source, path);
  r.first_run = count(e, "first_run", source, path);
  r.known_before = flag_field(e, "known_before", source, path);
  const json& c = field(e, "case", source, path);
  r.case_path = c.is_string() ? c.get<std::string>() : "";
  r.case_vehicles = count(e, "case_vehicles", source, path);
  r.shrink_steps = static_cast<int>(count(e, "shrink_steps", source, path));
  r.shrink_attempts = static_cast<int>(count(e, "shrink_attempts", source, path));
  r.shrink_minimal = flag_field(e, "shrink_minimal", source, path);
  r.first_run_guided = e.contains("first_run_guided") && flag_field(e, "first_run_guided", source, path);
  r.example.property = r.signature.property;
  r.example.rule = r.signature.rule;
  return r;
}

CampaignOptions options_of(const json& j, const std::string& source) {
  CampaignOptions o;
  o.planner = text_field(j, "planner", source, "");
  o.seed = count(j, "seed", source, "");
  if (const json& runs = field(j, "runs", source, ""); !runs.is_null()) o.runs = count(j, "runs", source, "");
  if (const json& t = field(j, "time_budget_s", source, ""); t.is_number()) o.time_s = t.get<double>();
  o.jobs = static_cast<int>(count(j, "jobs", source, ""));
  o.corpus_dir = text_field(j, "corpus", source, "");
  o.gen.targeted_families = text_field(j, "families", source, "") == "mixed";
  if (j.contains("search")) {  // reports of releases before guided search have none: random
    const auto mode = search_mode_from_string(text_field(j, "search", source, ""));
    if (!mode) throw InputError(source, "/search", "expected random or guided");
    o.search = *mode;
  }
  const std::string shard = text_field(j, "shard", source, "");
  char extra = 0;
  if (std::sscanf(shard.c_str(), "%d/%d%c", &o.shard_index, &o.shard_count, &extra) != 2 || o.shard_count < 1 ||
      o.shard_index < 0 || o.shard_index >= o.shard_count)
    throw InputError(source, "/shard", "expected K/N, got '" + shard + "'");
  return o;
}

// An exec planner's process as a shard's summary names it (campaign_summary_json): what the
// planner said in hello, and its stderr logs.
json planner_process_of(const json& j, const std::string& path) {
  const auto p = j.find("planner_process");
  if (p == j.end() || p->is_null()) return nullptr;
  const json& hello = field(*p, "hello", path, "/planner_process");
  if (!field(hello, "name", path, "/planner_process/hello").is_string() ||
      !field(hello, "version", path, "/planner_process/hello").is_string())
    throw InputError(path, "/planner_process/hello", "expected {\"name\": string, \"version\": string}");
  const json& logs = field(*p, "logs", path, "/planner_process");
  if (!logs.is_array() || !std::all_of(logs.begin(), logs.end(), [](const json& l) { return l.is_string(); }))
    throw InputError(path, "/planner_process/logs", "expected an array of file names");
  return json{{"hello", hello}, {"logs", logs}};
}

Shard read_shard(const std::string& path) {
  const json j = parse_json_file(path);
  Shard s{path, options_of(j, path), {}};
  CampaignResult& r = s.result;
  r.scenarios = count(j, "scenarios", path, "");
  r.failing_scenarios = count(j, "violations", path, "");
  r.property_failures = count(j, "property_failures", path, "");
  const json& seconds = field(j, "seconds", path, "");
  if (!seconds.is_number()) throw InputError(path, "/seconds", "expected a number");
  r.seconds = seconds.get<double>();
  r.interrupted = flag_field(j, "interrupted", path, "");
  r.by_property = counts(j, "failures_by_property", path);
  r.by_rule = counts(j, "failures_by_rule", path);
  r.by_party = counts(j, "failures_by_party", path);
  if (j.contains("guided_runs")) r.guided_runs = count(j, "guided_runs", path, "");
  if (j.contains("guided_violations")) r.guided_failing_scenarios = count(j, "guided_violations", path, "");
  if (j.contains("first_failure_run") && !j.at("first_failure_run").is_null()) {
    r.first_failure_run = count(j, "first_failure_run", path, "");
    const json& t = field(j, "first_failure_s", path, "");
    if (!t.is_number()) throw InputError(path, "/first_failure_s", "expected a number");
    r.first_failure_s = t.get<double>();
  }
  // Summaries written before the field existed have no first_new_failure_run.
  if (j.contains("first_new_failure_run") && !j.at("first_new_failure_run").is_null()) {
    r.first_new_failure_run = count(j, "first_new_failure_run", path, "");
    const json& t = field(j, "first_new_failure_s", path, "");
    if (!t.is_number()) throw InputError(path, "/first_new_failure_s", "expected a number");
    r.first_new_failure_s = t.get<double>();
  }
  const json& list = field(j, "signature_list", path, "");
  if (!list.is_array()) throw InputError(path, "/signature_list", "expected an array");
  for (std::size_t i = 0; i < list.size(); ++i) {
    SignatureRecord rec = signature_of_entry(list[i], path, "/signature_list/" + std::to_string(i));
    r.signatures[rec.signature] = rec;
  }
  const json& margins = field(j, "margins", path, "");
  if (!margins.is_object()) throw InputError(path, "/margins", "expected an object");
  for (const auto& [rule, m] : margins.items()) r.margins[rule] = margin_of(m, path, "/margins/" + rule);
  const json& cases = field(j, "new_cases", path, "");
  if (!cases.is_array() || !std::all_of(cases.begin(), cases.end(), [](const json& c) { return c.is_string(); }))
    throw InputError(path, "/new_cases", "expected an array of file names");
  for (const json& c : cases) r.new_cases.push_back(c.get<std::string>());
  r.planner_process = planner_process_of(j, path);
  return s;
}

// The shards must be slices of one campaign.
void check_same_campaign(const std::vector<Shard>& shards, bool partial) {
  const CampaignOptions& first = shards.front().options;
  std::set<int> seen;
  for (const Shard& s : shards) {
    const CampaignOptions& o = s.options;
    if (o.planner != first.planner || o.seed != first.seed || o.runs != first.runs || o.time_s != first.time_s ||
        o.gen.targeted_families != first.gen.targeted_families || o.search != first.search ||
        o.shard_count != first.shard_count)
      throw InputError(s.path, "", "not a shard of the campaign of " + shards.front().path +
                                       " (planner, seed, --runs/--time, --families, --search and N of --shard K/N must match)");
    if (!seen.insert(o.shard_index).second) throw InputError(s.path, "/shard", "shard " + std::to_string(o.shard_index) + " given twice");
    const json& hello = s.result.planner_process.is_object() ? s.result.planner_process["hello"] : json();
    const json& first_hello = shards.front().result.planner_process.is_object()
                                  ? shards.front().result.planner_process["hello"]
                                  : json();
    if (hello != first_hello)
      throw InputError(s.path, "/planner_process/hello", "its planner process is not the one of " + shards.front().path +
                                                             " (name and version from hello must match)");
  }
  if (!partial && static_cast<int>(seen.size()) != first.shard_count)
    throw InputError(shards.front().path, "/shard", std::to_string(first.shard_count - static_cast<int>(seen.size())) + " of " +
                                                        std::to_string(first.shard_count) + " shards missing (--partial merges what is there)");
}

void add_into(CampaignResult& into, const CampaignResult& r) {
  into.scenarios += r.scenarios;
  into.failing_scenarios += r.failing_scenarios;
  into.property_failures += r.property_failures;
  into.seconds = std::max(into.seconds, r.seconds);  // shards run side by side
  into.interrupted = into.interrupted || r.interrupted;
  into.guided_runs += r.guided_runs;
  into.guided_failing_scenarios += r.guided_failing_scenarios;
  if (r.first_failure_run && (!into.first_failure_run || *r.first_failure_run < *into.first_failure_run))
    into.first_failure_run = r.first_failure_run;
  if (r.first_failure_s && (!into.first_failure_s || *r.first_failure_s < *into.first_failure_s))  // shards run side by side
    into.first_failure_s = r.first_failure_s;
  if (r.first_new_failure_run && (!into.first_new_failure_run || *r.first_new_failure_run < *into.first_new_failure_run))
    into.first_new_failure_run = r.first_new_failure_run;
  if (r.first_new_failure_s && (!into.first_new_failure_s || *r.first_new_failure_s < *into.first_new_failure_s))
    into.first_new_failure_s = r.first_new_failure_s;
  for (const auto& [k, n] : r.by_property) into.by_property[k] += n;
  for (const auto& [k, n] : r.by_rule) into.by_rule[k] += n;
  for (const auto& [k, n] : r.by_party) into.by_party[k] += n;
  for (const auto& [sig, rec] : r.signatures) {
    auto [it, inserted] = into.signatures.try_emplace(sig, rec);
    if (inserted) continue;
    SignatureRecord& kept = it->second;
    const std::uint64_t total = kept.count + rec.count;
    const bool known = kept.known_before || rec.known_before;
    if (rec.first_run < kept.first_run) kept = rec;  // the lowest failing run's case, as one campaign keeps
    kept.count = total;
    kept.known_before = known;
  }
  for (const auto& [rule, m] : r.margins) into.margins[rule].merge(m);
  into.new_cases.insert(into.new_cases.end(), r.new_cases.begin(), r.new_cases.end());
  if (r.planner_process.is_object()) {  // the same process everywhere (check_same_campaign); every shard's logs
    if (!into.planner_process.is_object()) into.planner_process = {{"hello", r.planner_process["hello"]}, {"logs", json::array()}};
    for (const json& log : r.planner_process["logs"]) into.planner_process["logs"].push_back(log);
  }
}

}  // namespace

MergedReport merge_reports(const std::vector<std::string>& report_paths, bool partial) {
  if (report_paths.empty()) throw InputError("report merge", "", "no report.json given");
  std::vector<Shard> shards;
  for (const std::string& p : report_paths) shards.push_back(read_shard(p));
  check_same_campaign(shards, partial);
  std::stable_sort(shards.begin(), shards.end(),
                   [](const Shard& a, const Shard& b) { return a.options.shard_index < b.options.shard_index; });
  MergedReport m;
  m.options = shards.front().options;
  m.options.jobs = 0;
  m.shard_count = m.options.shard_count;
  for (const Shard& s : shards) {
    add_into(m.result, s.result);
    m.options.jobs += s.options.jobs;
    m.shards.push_back(s.options.shard_index);
  }
  std::sort(m.shards.begin(), m.shards.end());
  std::sort(m.result.new_cases.begin(), m.result.new_cases.end());
  if (m.complete()) {
    m.options.shard_index = 0;
    m.options.shard_count = 1;
  }
  return m;
}

}  // namespace mg::fuzz
