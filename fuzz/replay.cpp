#include "fuzz/replay.h"

#include <cmath>
#include <sstream>

namespace mg::fuzz {
namespace {

std::string describe(const CaseViolation& v) {
  std::ostringstream out;
  out << v.rule << " (liable " << party_name(v.liable_id) << ", t=";
  if (v.time_s) out << *v.time_s << " s"; else out << "-";
  out << ", margin " << v.margin << (v.unit.empty() ? "" : " ") << v.unit << ")";
  return out.str();
}

bool close_enough(const CaseViolation& a, const CaseViolation& b) {
  if (a.rule != b.rule || a.liable_id != b.liable_id || a.time_s.has_value() != b.time_s.has_value()) return false;
  if (a.time_s && std::abs(*a.time_s - *b.time_s) > kReplayTimeToleranceS) return false;
  const double tol = kReplayMarginAbsTolerance + kReplayMarginRelTolerance * std::abs(a.margin);
  return std::abs(a.margin - b.margin) <= tol;
}

}  // namespace

std::vector<std::string> compare_verdicts(const CaseVerdict& expected, const CaseVerdict& actual) {
  std::vector<std::string> diffs;
  auto yes_no = [](bool b) { return b ? std::string("true") : std::string("false"); };
  if (expected.holds != actual.holds)
    diffs.push_back("holds: expected " + yes_no(expected.holds) + ", got " + yes_no(actual.holds));
  if (expected.collision != actual.collision)
    diffs.push_back("collision: expected " + yes_no(expected.collision) + ", got " + yes_no(actual.collision));
  else if (expected.collision && expected.collision_liable_id != actual.collision_liable_id)
    diffs.push_back("collision liable: expected " + party_name(expected.collision_liable_id) + ", got " +
                    party_name(actual.collision_liable_id));
  std::vector<bool> matched(actual.violations.size(), false);
  for (const CaseViolation& e : expected.violations) {
    bool found = false;
    for (std::size_t i = 0; i < actual.violations.size() && !found; ++i)
      if (!matched[i] && close_enough(e, actual.violations[i])) matched[i] = found = true;
    if (!found) diffs.push_back("violation not reproduced: " + describe(e));
  }
  for (std::size_t i = 0; i < actual.violations.size(); ++i)
    if (!matched[i]) diffs.push_back("unexpected violation: " + describe(actual.violations[i]));
  if (expected.failed_properties != actual.failed_properties) {
    std::string e, a;
    for (const Signature& s : expected.failed_properties) e += " " + s.key();
    for (const Signature& s : actual.failed_properties) a += " " + s.key();
    diffs.push_back("failed properties: expected [" + e + " ], got [" + a + " ]");
  }
  return diffs;
}

ReplayResult replay_case(const CorpusCase& c, const CheckFn& check) {
  ReplayResult r;
  r.actual = verdict_of(run_properties(c.scenario, check, c.signature.planner, /*check_determinism=*/true));
  r.differences = compare_verdicts(c.verdict, r.actual);
  r.reproduces = r.differences.empty();
  return r;
}

}  // namespace mg::fuzz
