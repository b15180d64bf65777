#include "fuzz/corpus_case.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string_view>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/json_reader.h"
#include "planner/planner_params.h"

namespace mg::fuzz {
namespace {

using nlohmann::json;
constexpr double kAnyReal = 1e300;

json signature_to_json(const Signature& s) {
  return {{"planner", s.planner}, {"property", s.property}, {"rule", s.rule}, {"party", s.party}};
}

Signature signature_from(const ObjectReader& r) {
  r.only_keys({"planner", "property", "rule", "party"});
  Signature s{r.string("planner"), r.string("property"), r.string("rule"), r.string("party")};
  if (s.party != "ego" && s.party != "vehicle" && s.party != "none")
    r.fail("party", "must be \"ego\", \"vehicle\" or \"none\"");
  return s;
}

// A liable party as a case writes it (Party::code; the main lane is never liable), refused
// with an InputError when it names no party.
Party party_from_code(const ObjectReader& r, std::string_view key, long long code) {
  const std::optional<Party> party = Party::from_code(static_cast<int>(code));
  if (!party) r.fail(key, "is not a party code (-1 none, 0 ego, >= 1 a vehicle id)");
  return *party;
}

Party liable_from(const ObjectReader& r) {
  return party_from_code(r, "liable_id", r.integer("liable_id", Party::nobody().code(), 1000000));
}

json failure_to_json(const PropertyFailure& f) {
  return {{"property", f.property}, {"rule", f.rule},     {"liable_id", f.liable_id.code()}, {"liable", party_name(f.liable_id)},
          {"time_s", f.time_s},     {"margin", f.margin}, {"detail", f.detail}};
}

PropertyFailure failure_from(const ObjectReader& r) {
  r.only_keys({"property", "rule", "liable_id", "liable", "time_s", "margin", "detail"});
  return {r.string("property"), r.string("rule"), liable_from(r), r.number("time_s", 0.0, kAnyReal),
          r.number("margin", -kAnyReal, kAnyReal), r.string_or("detail", "")};
}

json violation_to_json(const CaseViolation& v) {
  json j = {{"rule", v.rule}, {"liable_id", v.liable_id.code()}, {"liable", party_name(v.liable_id)},
            {"margin", v.margin}, {"unit", v.unit}};
  j["time_s"] = v.time_s ? json(*v.time_s) : json(nullptr);
  return j;
}

CaseViolation violation_from(const ObjectReader& r) {
  r.only_keys({"rule", "liable_id", "liable", "time_s", "margin", "unit"});
  CaseViolation v{r.string("rule"), liable_from(r), std::nullopt, r.number("margin", -kAnyReal, kAnyReal),
                  r.string_or("unit", "")};
  if (!r.has("time_s")) r.fail("time_s", "missing required key (null when the rule held)");
  if (!r.value().at("time_s").is_null()) v.time_s = r.number("time_s", 0.0, kAnyReal);
  return v;
}

json verdict_to_json(const CaseVerdict& v) {
  json violations = json::array();
  for (const CaseViolation& x : v.violations) violations.push_back(violation_to_json(x));
  json properties = json::array();
  for (const Signature& s : v.failed_properties) properties.push_back(signature_to_json(s));
  return {{"holds", v.holds},
          {"collision", v.collision},
          {"collision_liable_id", v.collision_liable_id.code()},
          {"collision_liable", party_name(v.collision_liable_id)},
          {"violations", violations},
          {"failed_properties", properties},
          {"trace_digest", v.trace_digest}};
}

std::uint64_t unsigned_from(const ObjectReader& r, std::string_view key) {
  if (!r.has(key)) r.fail(key, "missing required key");
  const json& v = r.value().at(std::string(key));
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<long long>() >= 0))
    r.fail(key, "expected a non-negative integer");
  return v.get<std::uint64_t>();
}

CaseVerdict verdict_from(const ObjectReader& r) {
  r.only_keys({"holds", "collision", "collision_liable_id", "collision_liable", "violations", "failed_properties",
               "trace_digest"});
  CaseVerdict v;
  if (!r.has("holds")) r.fail("holds", "missing");
  v.holds = r.boolean_or("holds", true);
  v.collision = r.boolean_or("collision", false);
  v.collision_liable_id = party_from_code(
      r, "collision_liable_id",
      r.integer_or("collision_liable_id", Party::nobody().code(), Party::nobody().code(), 1000000));
  const json& violations = r.array("violations");
  for (std::size_t i = 0; i < violations.size(); ++i)
    v.violations.push_back(violation_from(ObjectReader(violations[i], r.source(), r.path_of("violations") + "/" + std::to_string(i))));
  const json& properties = r.array("failed_properties");
  for (std::size_t i = 0; i < properties.size(); ++i)
    v.failed_properties.push_back(
        signature_from(ObjectReader(properties[i], r.source(), r.path_of("failed_properties") + "/" + std::to_string(i))));
  if (r.has("trace_digest")) v.trace_digest = unsigned_from(r, "trace_digest");
  return v;
}

json provenance_to_json(const Provenance& p) {
  return {{"found_by", p.found_by},         {"campaign_seed", p.campaign_seed}, {"run_index", p.run_index},
          {"shrink_steps", p.shrink_steps}, {"shrink_attempts", p.shrink_attempts},
          {"shrink_minimal", p.shrink_minimal}, {"date", p.date}};
}

Provenance provenance_from(const ObjectReader& r) {
  r.only_keys({"found_by", "campaign_seed", "run_index", "shrink_steps", "shrink_attempts", "shrink_minimal", "date"});
  Provenance p;
  p.found_by = r.string("found_by");
  p.campaign_seed = unsigned_from(r, "campaign_seed");
  p.run_index = unsigned_from(r, "run_index");
  p.shrink_steps = static_cast<int>(r.integer("shrink_steps", 0, 1000000000));
  p.shrink_attempts = static_cast<int>(r.integer("shrink_attempts", 0, 1000000000));
  p.shrink_minimal = r.boolean_or("shrink_minimal", false);
  p.date = r.string("date");
  return p;
}

}  // namespace

CaseVerdict verdict_of(const RunOutcome& outcome) {
  CaseVerdict v;
  if (outcome.result) {
    const CheckResult& result = *outcome.result;
    v.holds = result.holds;
    v.collision = result.collision;
    v.collision_liable_id = result.collision ? result.collision_liable_id : Party::nobody();
    for (const RuleResult& r : result.rules)
      if (!r.holds) v.violations.push_back({r.rule_id, r.liable_id, r.first_violation_time_s, r.min_margin, r.unit});
    v.trace_digest = result.trace_digest;
  } else {
    v.holds = false;  // the check threw
  }
  for (const PropertyFailure& f : outcome.failures) v.failed_properties.push_back(signature_of(outcome.planner, f));
  std::sort(v.failed_properties.begin(), v.failed_properties.end());
  v.failed_properties.erase(std::unique(v.failed_properties.begin(), v.failed_properties.end()),
                            v.failed_properties.end());
  return v;
}

json case_to_json(const CorpusCase& c) {
  json j = {{"format_version", c.format_version},
          {"signature", signature_to_json(c.signature)},
          {"planner", c.signature.planner},
          {"property", c.signature.property},
          {"failure", failure_to_json(c.failure)},
          {"verdict", verdict_to_json(c.verdict)},
          {"provenance", provenance_to_json(c.provenance)},
          {"scenario", scenario_to_json(c.scenario)}};
  if (c.planner_hello) j["planner_hello"] = {{"name", c.planner_hello->name}, {"version", c.planner_hello->version}};
  return j;
}

CorpusCase case_from_json(const json& j, const std::string& source) {
  const ObjectReader r(j, source, "");
  // The version first: a newer file may have keys this build does not know.
  const long long version = r.integer("format_version", 1, 1000000);
  if (version > kCorpusFormatVersion)
    r.fail("format_version", "format version " + std::to_string(version) + " is newer than this mergeguard reads (" +
                                 std::to_string(kCorpusFormatVersion) + ")");
  r.only_keys({"format_version", "signature", "planner", "property", "failure", "verdict", "provenance", "scenario",
               "planner_hello"});
  CorpusCase c;
  c.format_version = static_cast<int>(version);
  c.signature = signature_from(r.object("signature"));
  if (r.string("planner") != c.signature.planner) r.fail("planner", "differs from /signature/planner");
  if (r.string("property") != c.signature.property) r.fail("property", "differs from /signature/property");
  c.failure = failure_from(r.object("failure"));
  c.verdict = verdict_from(r.object("verdict"));
  c.provenance = provenance_from(r.object("provenance"));
  if (r.has("planner_hello")) {
    const ObjectReader hello = r.object("planner_hello");
    hello.only_keys({"name", "version"});
    c.planner_hello = PlannerIdentity{hello.string("name"), hello.string("version")};
  }
  if (!j.contains("scenario")) r.fail("scenario", "missing");
  c.scenario = planner_scenario_from_json(j.at("scenario"), source + " (/scenario)");
  return c;
}

CorpusCase load_case(const std::string& path) { return case_from_json(parse_json_file(path), path); }

void write_case(const CorpusCase& c, const std::string& path) { write_file_atomic(path, case_to_json(c).dump(2) + "\n"); }

std::vector<std::string> case_files(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return {path};
  if (!fs::is_directory(path, ec)) throw InputError(path, "", "no such case file or directory");
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(path, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::set<Signature> corpus_signatures(const std::string& dir) {
  std::set<Signature> known;
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return known;
  for (const std::string& file : case_files(dir)) {
    const CorpusCase c = load_case(file);
    const auto& failed = c.verdict.failed_properties;
    if (std::find(failed.begin(), failed.end(), c.signature) != failed.end()) known.insert(c.signature);
  }
  return known;
}

std::string free_case_path(const std::string& dir, const std::string& stem) {
  namespace fs = std::filesystem;
  fs::path path = fs::path(dir) / (stem + ".json");
  for (int n = 2; fs::exists(path); ++n) path = fs::path(dir) / (stem + "-" + std::to_string(n) + ".json");
  return path.string();
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

}  // namespace mg::fuzz
